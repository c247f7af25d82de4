#!/usr/bin/env bash
# Installs the Debian 12 packages icpbench builds and runs with (as root, or
# with sudo). Packages already present are left alone.
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config git
  libboost-dev libeigen3-dev libtbb-dev libopencv-dev libsqlite3-dev sqlite3
  libyaml-cpp-dev libcli11-dev nlohmann-json3-dev
  libboost-iostreams-dev libboost-filesystem-dev libboost-system-dev
  libgtest-dev libgmock-dev libbenchmark-dev libmpfr-dev libgmp-dev
  gnuplot-nox libgnuplot-iostream-dev
  libopenmpi-dev openmpi-bin  # run --mpi (a build without them has no --mpi)
  libmrpt-bayes-dev  # optional: the particle filter's cross-check against MRPT's
  clang libclang-rt-14-dev  # scripts/fuzz.sh: clang++ and its libFuzzer/ASan runtimes
  # icpbench paper: pdflatex (base; recommended for booktabs), latexmk, and
  # pdftotext for its test; about 150 MB installed, a minute to install.
  texlive-latex-base texlive-latex-recommended latexmk poppler-utils
  # The Python module (python/, docs/python.md) and its pytest suite.
  pybind11-dev python3-dev python3-numpy python3-pandas python3-pytest python3-matplotlib
  # icpbench serve (docs/web.md): the HTTP server, the page's charts, and the
  # headless browser its test drives.
  libcpp-httplib-dev libjs-chart.js chromium
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  echo "icpbench: installing ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
