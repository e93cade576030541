#!/usr/bin/env bash
# Installs the Debian 12 packages that building and rendering need (the program, the Python
# package, the .deb), only those that are missing, and the page's npm packages (web/); with
# --tests, the test tools too (GoogleTest, pytest, the sanitizers' clang, the fuzzer, Chromium,
# Slurm, the benchmarks' peers).
# Idempotent and quiet when everything is already there. Runs apt-get as root or through sudo.
set -euo pipefail

case "${1:-}" in
  "") tests=false ;;
  --tests) tests=true ;;
  *) echo "setup: unknown argument '$1'; run setup.sh (building and rendering) or setup.sh --tests (and testing)" >&2; exit 1 ;;
esac

packages=(
  build-essential cmake pkg-config
  file                                            # the .deb (cpack -G DEB): its dependencies, found by dpkg-shlibdeps
  libeigen3-dev                                   # math
  libccd-dev                                      # GJK and EPA: where two convex shapes without a formula of their own meet (physics/collide_convex.cpp)
  libqhull-dev                                    # convex hulls: a hull shape's faces from its points (physics/hull.cpp)
  libtinyobjloader-dev                            # Wavefront OBJ files: a mesh shape's triangles (demos/scene/scene_mesh.cpp)
  libtinygltf-dev                                 # glTF 2.0 files: `impulse export --format glb` (demos/page/page_glb.cpp)
  libcpp-httplib-dev                              # impulse preview's server on 127.0.0.1 (demos/page/page_preview.cpp)
  zlib1g-dev libglib2.0-dev                       # a page's run, gzip and base64 (demos/page/page_export.cpp)
  libegl-dev libegl-mesa0 libgl1-mesa-dri         # offscreen OpenGL through EGL (a GPU, else Mesa's llvmpipe)
  libosmesa6-dev                                  # ... or through OSMesa (llvmpipe; gone from Mesa 25.1)
  python3-glad                                    # the OpenGL loader, generated at build time
  libpng-dev                                      # PNG frames
  libavcodec-dev libavformat-dev libswscale-dev libavutil-dev libavfilter-dev   # H.264 MP4, VP9 WebM, GIF (libx264, libvpx inside; GIF's palettes by libavfilter)
  libtomlplusplus-dev                             # scene files
  libcli11-dev                                    # command line
  nodejs                                          # the page's viewer (web/), bundled at build time by esbuild
  libseccomp-dev                                  # the sandbox of students' code (demos/response)
  libcairo2-dev fonts-dejavu-core                 # 2D overlays and their font
  libpango1.0-dev fonts-noto-core fonts-noto-color-emoji   # ... characters DejaVu lacks (emoji, rarer scripts and signs), from Noto through Pango's fallback
  texlive-latex-base dvisvgm librsvg2-dev         # typeset equations: LaTeX -> SVG (tex/), drawn by librsvg
  pybind11-dev python3-dev python3-numpy         # the Python package (demos/python), for Debian's python3
  python3-tqdm python3-matplotlib python3-pandas  # ... its progress bar, and what its notebook plots and tabulates
)
$tests && packages+=(
  libgtest-dev                                    # tests
  nlohmann-json3-dev                              # tests: reading the JSON the program writes (--layout-report)
  python3-pytest python3-nbconvert python3-ipykernel   # tests: the Python package, the notebook in a real kernel
  libbullet-dev                                   # benchmark peer only
  ffmpeg                                          # benchmark peer only (render_bench's naive path); impulse never runs it
  clang libclang-rt-14-dev                        # tests: the libFuzzer target (tests/fuzz; clang's fuzzer and sanitizer runtimes)
  llvm                                            # tests: llvm-symbolizer, for the sanitizers' stack traces
  lld                                             # tests: the sanitizer builds' linker
  chromium python3                                # tests: the gallery opened in headless Chromium, served by Python's http.server
  slurmctld slurmd slurm-client munge             # tests: the Slurm example (docs/autograders/slurm) on a one-node Slurm
  qemu-user                                       # tests: the solve's clones for older CPUs run under an emulated one (tests/physics)
)

command -v npm >/dev/null || packages+=(npm)   # the page's packages (web/), where Node.js came without it

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  as_root=()
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "setup: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
    as_root=(sudo)
  fi
  echo "setup: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  "${as_root[@]}" apt-get update -qq
  "${as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# The page's viewer (web/): three.js and esbuild from the npm registry, exactly as
# web/package-lock.json pins them; installed again only when the lock file changed.
cd "$(dirname "$0")/../web"
if [ ! -f node_modules/.package-lock.json ] || [ package-lock.json -nt node_modules/.package-lock.json ]; then
  echo "setup: installing the page's npm packages (web/package-lock.json)" >&2
  npm ci --no-audit --no-fund --loglevel=error >/dev/null ||
    { echo "setup: npm ci in web/ failed: the page's three.js and esbuild come from the npm registry" >&2; exit 1; }
fi
