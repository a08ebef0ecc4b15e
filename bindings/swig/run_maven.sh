#!/bin/sh
# ctest entry for the JUnit 5 suite: `mvn -B -ntp test` against the native libraries in $1 (the build
# dir of bindings/swig). Tries offline (-o) first when ~/.m2 already holds JUnit; if Maven then fails
# to resolve an artifact offline, it runs again online. Never -q (Surefire's "Tests run:" line is read).
# Usage: run_maven.sh <native-dir> <pom.xml> [mvn]
dir="$1"; pom="$2"; mvn="${3:-mvn}"
if [ -d "$HOME/.m2/repository/org/junit/jupiter/junit-jupiter-engine" ]; then
  log=$(mktemp) || exit 1
  "$mvn" -B -ntp -o -f "$pom" test -Do3d.swig.dir="$dir" 2>&1 | tee "$log"
  rc=$?
  # POSIX sh has no pipefail: read Maven's verdict from the log.
  if grep -q "BUILD SUCCESS" "$log"; then rm -f "$log"; exit 0; fi
  if ! grep -qE "offline mode|has not been downloaded|Cannot access .* in offline" "$log"; then rm -f "$log"; exit 1; fi
  rm -f "$log"
  echo "run_maven.sh: offline resolution failed (rc $rc), retrying online"
fi
exec "$mvn" -B -ntp -f "$pom" test -Do3d.swig.dir="$dir"
