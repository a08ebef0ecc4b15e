#!/usr/bin/env bash
# Installs everything o3d needs on a bare Debian 12 machine (run as root, or with sudo available).
# Idempotent: packages already present are left alone. Set O3D_SKIP_INSTALL=1 to skip.
set -euo pipefail
[ "${O3D_SKIP_INSTALL:-0}" = "1" ] && exit 0

SUDO=""
if [ "$(id -u)" != "0" ]; then SUDO="sudo"; fi

PACKAGES=(
  # build
  cmake ninja-build pkg-config g++ clang libclang-dev doxygen git ca-certificates
  # core
  libeigen3-dev libflann-dev liblz4-dev liblzf-dev libqhull-dev
  # images, meshes and camera files
  libpng-dev libjpeg-dev libtinyobjloader-dev libtinygltf-dev nlohmann-json3-dev
  # rendering: OpenGL through libepoxy, EGL (Mesa: software rendering without a display), GLFW; Xvfb for
  # the tests that need a window
  libepoxy-dev libglfw3-dev libglfw3 libegl1 libegl-mesa0 libgl1-mesa-dri libopengl0 libgl1 xvfb xauth
  # tests and checks
  libcmocka-dev libgtest-dev abigail-tools valgrind
  # python
  python3 python3-dev python3-venv python3-pip
  # C# and Java through SWIG
  swig mono-mcs mono-runtime openjdk-17-jdk-headless maven
  # packages that carry their native libraries (jar, Unity, wheel): RUNPATH rewriting
  patchelf
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "install-deps: apt-get install ${missing[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# Rust: the machine's rustup toolchain when present, else Debian's cargo (the crates need no newer features).
if ! command -v cargo >/dev/null 2>&1 && [ ! -x "$HOME/.cargo/bin/cargo" ]; then
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends cargo rustc
fi
echo "install-deps: done"
