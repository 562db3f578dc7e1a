#!/usr/bin/env bash
# cmake --install (into a DESTDIR), then: the binary runs, python3 imports the module from where
# it was installed, and a tiny C++ project builds against find_package(usvid) and runs.
set -euo pipefail
build=$1 source=$2 python=$3
work=$(mktemp -d "${TMPDIR:-/tmp}/usvid_install_XXXXXX")
trap 'rm -rf "$work"' EXIT
DESTDIR=$work/root cmake --install "$build" --prefix /opt/usvid >"$work/install.log"
root=$work/root
"$root/opt/usvid/bin/usvid" --version
site=$(grep -o '^USVID_PYTHON_INSTALL_DIR:PATH=.*' "$build/CMakeCache.txt" | cut -d= -f2 || true)
if [ -n "$site" ]; then
  PYTHONPATH=$root$site "$python" -c \
    "import usvid; d = usvid.simulate(vessel='msd', maneuver='random-steps', duration=10); print('python:', len(d['t']), 'rows')"
fi
cmake -S "$source/tests/install/consumer" -B "$work/consumer" -G Ninja \
  -DCMAKE_PREFIX_PATH="$root/opt/usvid" -DCMAKE_BUILD_TYPE=Release >"$work/configure.log"
cmake --build "$work/consumer" >"$work/build.log" || { cat "$work/build.log"; exit 1; }
"$work/consumer/consumer"
