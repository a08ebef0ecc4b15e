#!/usr/bin/env bash
# The README's test command: installs what is needed, builds, and runs every test suite:
# C++ core tests, C API tests (plain and under ASan+UBSan), the dlopen test, the C++ wrapper,
# the examples, C#, Java, Python, Rust, the ABI check and the binding-coverage check, and every package
# (install prefix, jar, Unity package, wheel, crates) used by a consumer outside the tree.
# Environment: O3D_TEST_DATA (default ../shared/data), O3D_REQUIRE_TEST_DATA=1 (CI: missing data fails),
# O3D_SKIP_INSTALL=1 (skip apt), O3D_JOBS (default: number of cores).
set -uo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
export O3D_TEST_DATA="${O3D_TEST_DATA:-$ROOT/../shared/data}"
JOBS="${O3D_JOBS:-$(nproc)}"
export CMAKE_BUILD_PARALLEL_LEVEL="$JOBS" CARGO_BUILD_JOBS="$JOBS"
export PATH="$HOME/.cargo/bin:$PATH"
if [ -z "${JAVA_HOME:-}" ]; then
  for j in /usr/lib/jvm/java-17-openjdk-amd64 /usr/lib/jvm/default-java; do [ -d "$j" ] && export JAVA_HOME=$j && break; done
fi

scripts/install-deps.sh || { echo "install-deps failed"; exit 1; }

passed=0; failed=0; failed_steps=()
step() {
  local name=$1; shift
  echo; echo "=== $name ==="
  local t0=$SECONDS
  if "$@"; then passed=$((passed+1)); echo "=== $name: ok ($((SECONDS-t0)) s)";
  else failed=$((failed+1)); failed_steps+=("$name"); echo "=== $name: FAILED ($((SECONDS-t0)) s)"; fi
}

build_main() {
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DO3D_BUILD_SWIG=ON >/dev/null &&
  cmake --build build -j"$JOBS"
}
ctest_main() { ctest --test-dir build --output-on-failure -j"$JOBS" --timeout 600; }
build_sanitized() {
  cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DO3D_SANITIZE=ON -DO3D_BUILD_EXAMPLES=OFF >/dev/null &&
  cmake --build build-asan -j"$JOBS"
}
# Sanitized run: the C API suites (incl. dlopen), the parser fuzz replay and the core tests.
ctest_sanitized() {
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir build-asan --output-on-failure -j"$JOBS" --timeout 900 -L 'capi|fuzz|core|cpp'
}
abi_check() { tools/abi_check.sh build; }
# The C headers are the source the bindings are derived from: every function fully documented, and
# the Doxygen reference builds without a warning.
capi_docs() { python3 tools/check_capi_docs.py && tools/gen_capi_reference.sh build/capi-reference; }
# The bindings' enums and option-struct tables are generated from the headers: the committed files must match.
binding_tables() { python3 tools/gen_binding_tables.py --check; }
# After the Python install: Python's reach is read from the symbols its extension imports.
coverage_check() {
  local ext; ext=$(ls .venv/lib/python3*/site-packages/o3d/_o3d*.so 2>/dev/null | head -1)
  python3 tools/check_binding_coverage.py --lib build/capi/libo3d.so ${ext:+--python-ext "$ext"}
}
# The wheel as users get it: built, repaired by auditwheel (it carries the libraries it links), checked
# with ldd, imported outside the tree; then the Python tests run on that very wheel.
python_wheel() { rm -rf build-wheel && scripts/check_python_wheel.sh python3 "$ROOT/build-wheel"; }
python_tests() {
  [ -x .venv/bin/python ] || python3 -m venv .venv || return 1
  .venv/bin/pip install -q --upgrade pip >/dev/null 2>&1
  .venv/bin/pip install -q numpy pytest || return 1
  .venv/bin/pip install -q --force-reinstall --no-deps build-wheel/o3d-*.whl || return 1
  (cd bindings/python/tests && "$ROOT/.venv/bin/python" -m pytest -q -p no:cacheprovider)
}
python_examples() {
  local out; out=$(mktemp -d)
  .venv/bin/python examples/python/figure1.py "$O3D_TEST_DATA/open3d/Feature/cloud_bin_0.pcd" "$out/down.ply" &&
  .venv/bin/python examples/python/icp.py "$O3D_TEST_DATA/open3d/Feature/cloud_bin_0.pcd" \
      "$O3D_TEST_DATA/open3d/Feature/cloud_bin_1.pcd" 0.05 &&
  .venv/bin/python examples/python/rgbd_to_point_cloud.py "$O3D_TEST_DATA/open3d/RGBD/color/00000.jpg" \
      "$O3D_TEST_DATA/open3d/RGBD/depth/00000.png" "$out/frame.ply" &&
  .venv/bin/python examples/python/mesh_cleanup.py "$O3D_TEST_DATA/open3d/knot.ply" "$out/knot_clean.ply" \
      "$out/knot_samples.ply" &&
  .venv/bin/python examples/python/multiway_registration.py "$O3D_TEST_DATA/livingroom1_clean_micro" &&
  .venv/bin/python examples/python/figure2.py "$O3D_TEST_DATA/open3d/Feature/cloud_bin_0.pcd" \
      "$O3D_TEST_DATA/open3d/knot.ply" --frames 5 --out "$out/figure2"
}
# JUnit already ran in ctest (java_junit, on the same classes, loading the natives as the jar does).
java_package() { (cd bindings/java && mvn -B -ntp -q package -DskipTests -Do3d.swig.dir="$ROOT/build/bindings/swig"); }
rust_tests() { (cd bindings/rust && O3D_LIB_DIR="$ROOT/build/capi" O3D_INCLUDE_DIR="$ROOT/capi/include" cargo test 2>&1); }
rust_example() {
  local out; out=$(mktemp -d)
  (cd bindings/rust && export O3D_LIB_DIR="$ROOT/build/capi" O3D_INCLUDE_DIR="$ROOT/capi/include" &&
   cargo run -q --example figure1 -- "$O3D_TEST_DATA/open3d/Feature/cloud_bin_0.pcd" "$out/down.ply" &&
   cargo run -q --example figure2 -- "$out/figure2" 12 &&
   cargo run -q --example global_registration -- \
      "$O3D_TEST_DATA/open3d/Feature/cloud_bin_0.pcd" "$O3D_TEST_DATA/open3d/Feature/cloud_bin_1.pcd")
}
# The crates as cargo packages them, used by a consumer outside the tree that finds libo3d through the
# installed prefix's pkg-config only.
rust_package() { local p; p=$(mktemp -d); cmake --install build --prefix "$p" >/dev/null && scripts/check_rust_package.sh "$p"; }

step "build" build_main
step "ctest: core, C API, dlopen, C++ wrapper, headers, examples, C#, Java smoke" ctest_main
step "build (ASan+UBSan)" build_sanitized
step "ctest under ASan+UBSan" ctest_sanitized
step "ABI check (abidiff against abi/)" abi_check
step "C API docs and reference" capi_docs
step "generated binding tables (tools/gen_binding_tables.py --check)" binding_tables
step "java: mvn package (the jar with its native libraries)" java_package
step "install + consumers outside the tree (CMake C/C++, pkg-config, dlopen, C#/Unity, Java jar)" \
  scripts/check_consumers.sh build bindings/java/target/o3d-0.1.0.jar
step "python: wheel (auditwheel repair, ldd, import outside the tree)" python_wheel
step "python: pytest (on that wheel)" python_tests
step "binding coverage" coverage_check
step "python: examples" python_examples
step "rust: cargo test" rust_tests
step "rust: examples" rust_example
step "rust: cargo package + consumer outside the tree" rust_package

echo
if [ $failed -gt 0 ]; then echo "failed suites: ${failed_steps[*]}"; fi
echo "suites: $passed passed, $failed failed"
[ $failed -eq 0 ]
