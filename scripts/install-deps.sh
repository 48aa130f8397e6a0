#!/usr/bin/env bash
# Installs the Debian 12 packages littermap needs, skipping those already installed.
#   scripts/install-deps.sh           build + test dependencies
#   scripts/install-deps.sh --ci      also clang (sanitizer and fuzz builds)
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libopencv-dev libsqlite3-dev zlib1g-dev libpng-dev libjpeg-dev
  libyaml-cpp-dev nlohmann-json3-dev libcli11-dev libzstd-dev liblz4-dev
  libgtest-dev libbenchmark-dev libceres-dev libnanoflann-dev ccache
  libproj-dev libtiff-dev libgeotiff-dev libpcl-dev libopenni2-dev
  python3 chromium nodejs gdal-bin poppler-utils
  libpq-dev postgresql-15 postgresql-15-postgis-3
)
# The interop tests read and write bags with pinned npm packages (tests/interop). Debian's
# nodejs comes without npm; NodeSource's includes it.
if ! command -v npm >/dev/null; then
  packages+=(npm)
fi
if [[ "${1:-}" == "--ci" ]]; then
  packages+=(clang libclang-rt-14-dev)
fi

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if [[ ${#missing[@]} -eq 0 ]]; then
  echo "littermap: all ${#packages[@]} system packages are installed"
  exit 0
fi

echo "littermap: installing ${missing[*]}"
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then
  if ! command -v sudo >/dev/null; then
    echo "littermap: missing packages (${missing[*]}); run this script as root" >&2
    exit 1
  fi
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
# The package lists of a fresh machine are empty: fetch them once, then install.
if ! "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null 2>&1; then
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
