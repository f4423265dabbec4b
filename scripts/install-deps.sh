#!/usr/bin/env bash
# Installs the Debian 12 packages the toolkit builds against, only those missing.
# Idempotent: a second run installs nothing and takes about a second. Needs root (or sudo).
#   install-deps.sh              the build (the README's first command)
#   install-deps.sh --paraview   also ParaView, h5py and a virtual X server for the test that
#                                opens a run in ParaView (scripts/test.sh; about 185 packages,
#                                2-3 minutes on a fresh machine)
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  libcli11-dev nlohmann-json3-dev libvalijson-dev libeigen3-dev
  libhdf5-dev hdf5-tools libgmsh-dev libcairo2-dev
  libgtest-dev libgmock-dev
  clang libclang-rt-14-dev libomp-dev # the sanitizer and fuzz build (scripts/build-sanitize.sh)
)
if [ "${1:-}" = "--paraview" ]; then
  packages+=(paraview python3-paraview python3-h5py xvfb xauth)
elif [ $# -gt 0 ]; then
  echo "install-deps: unknown option $1 (only --paraview)" >&2
  exit 2
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
