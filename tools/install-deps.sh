#!/usr/bin/env bash
# Installs what usvid needs from Debian 12's packages.
#   tools/install-deps.sh          what the build needs (the README's first command)
#   tools/install-deps.sh --test   that, and the test command's tools: clang 14 with its
#                                  sanitizers, libFuzzer and OpenMP, OpenMPI, and Chromium for the
#                                  report's rendering test (some 1 GB more), and Universal
#                                  Ctags for the architecture test's function-length rule
set -euo pipefail
packages=(g++ cmake ninja-build ccache git
  libeigen3-dev libceres-dev libnlopt-cxx-dev libgtest-dev libgmock-dev libbenchmark-dev
  libcli11-dev nlohmann-json3-dev libyaml-cpp-dev
  pybind11-dev python3-dev python3-numpy)  # the Python module
case "${1:-}" in
  --test)
    packages+=(clang-14 libclang-rt-14-dev libomp-14-dev  # clang's sanitizers, libFuzzer, OpenMP
               openmpi-bin libopenmpi-dev                  # the MPI build (-DUSVID_WITH_MPI=ON)
               chromium                                    # the report's rendering test
               universal-ctags)                            # the function-length rule
    ;;
  "") ;;
  *)
    echo "usage: tools/install-deps.sh [--test]" >&2
    exit 2
    ;;
esac
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq "${missing[@]}" >/dev/null
fi
