#!/usr/bin/env bash
# Installs the Debian 12 packages stochtex needs, only those that are missing.
# Run as root (or with sudo available). Never downloads anything but Debian packages.
#   scripts/install-deps.sh           what the build and the tests need (clang and
#                                     libFuzzer too: `make test` runs a sanitizer build)
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libopencv-core-dev libopencv-imgproc-dev libopencv-imgcodecs-dev libopencv-video-dev libopencv-videoio-dev
  libtbb-dev nlohmann-json3-dev libcli11-dev libglm-dev libboost-math-dev
  libgtest-dev libgmock-dev libbenchmark-dev libhwy-dev
  libepoxy-dev libegl-dev libegl-mesa0 libgl1-mesa-dri glslang-tools glslang-dev spirv-tools libspirv-cross-c-shared-dev spirv-cross
  libglfw3-dev libimgui-dev xvfb xauth libpng-dev libwebp-dev libgif-dev libtinyobjloader-dev libtinygltf-dev
  libavcodec-dev libavformat-dev libavutil-dev libswscale-dev
  libplplot-dev plplot-driver-cairo libpango1.0-dev libcairo2-dev fonts-dejavu-core libjs-chart.js
  clang-14 libclang-rt-14-dev clang-format
  pybind11-dev python3-dev python3-numpy python3-pil python3-pytest python3-distributed python3-matplotlib python3-pandas python3-pip
  chromium
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then sudo_cmd=(sudo); else
    echo "install-deps: missing packages (${missing[*]}) and not root; run as root" >&2
    exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
