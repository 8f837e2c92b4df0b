#!/usr/bin/env bash
# Installs the Debian 12 packages that hairstyle needs to build and test
# (CMakeLists.txt and tests/CMakeLists.txt), and nothing else.
#
#   scripts/install-deps.sh            # as root, or through sudo
#   scripts/install-deps.sh --list     # print the package list and exit
#
# Idempotent: when every package is already installed it does nothing, not even
# `apt-get update`, and returns at once. OpenCV: only the modules we use
# (DESIGN.md: the whole libopencv-dev pulls in Qt and VTK). OpenMP comes with
# g++ (libgomp), so no libomp.
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake ninja-build pkg-config git
  # libraries (find_package / find_library in CMakeLists.txt)
  libeigen3-dev libassimp-dev libhdf5-dev libcli11-dev libspdlog-dev libfmt-dev
  libnanoflann-dev nlohmann-json3-dev libssl-dev libspectra-dev
  libsuitesparse-dev liblapack-dev zlib1g-dev libtomlplusplus-dev
  libboost-graph-dev  # Edmonds' matching: triangles paired back into quads
  libopencv-imgproc-dev libopencv-imgcodecs-dev libopencv-ml-dev
  libopencv-videoio-dev  # preview videos: MP4 through FFmpeg (libavcodec)
  # tests
  libgtest-dev libgmock-dev
  # the Blender add-on's test (blender/, tests/blender/): Debian's Blender runs on the
  # system Python, where python3-h5py reads the HDF5 files
  blender python3-h5py
  # the pipeline through a single-node Slurm (scripts/slurm-local.sh, tests/slurm/)
  slurm-wlm munge
  # h5ls, h5dump: to look into the pipeline's outputs
  hdf5-tools
  # functions' extents for the layout test (scripts/check-function-length.sh)
  universal-ctags
)

if [[ "${1:-}" == "--list" ]]; then
  printf '%s\n' "${packages[@]}"
  exit 0
fi

# One dpkg-query for all: "name status" per known package (unknown ones are left out).
installed=" $(dpkg-query -W -f='${Package}=${db:Status-Status} ' "${packages[@]}" 2>/dev/null || true)"
missing=()
for package in "${packages[@]}"; do
  [[ "$installed" == *" $package=installed "* ]] || missing+=("$package")
done

if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages are installed"
  exit 0
fi

sudo=()
if ((EUID != 0)); then
  command -v sudo >/dev/null || { echo "install-deps: run as root (or install sudo)" >&2; exit 1; }
  sudo=(sudo)
fi

echo "install-deps: installing ${missing[*]}"
"${sudo[@]}" apt-get update -q </dev/null
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y -q --no-install-recommends "${missing[@]}" </dev/null
