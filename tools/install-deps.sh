#!/usr/bin/env bash
# Installs what usvid needs to build and test on Debian 12, all from Debian's packages.
set -euo pipefail
packages=(g++ cmake ninja-build ccache git
  libeigen3-dev libceres-dev libnlopt-cxx-dev libgtest-dev libgmock-dev libbenchmark-dev
  libcli11-dev nlohmann-json3-dev
  clang-14 libclang-rt-14-dev libomp-14-dev  # clang's sanitizers, libFuzzer and OpenMP
  openmpi-bin libopenmpi-dev)  # the optional MPI build (-DUSVID_WITH_MPI=ON)
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
