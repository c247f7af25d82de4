# Sourced by scripts/build.sh and scripts/asan_build.sh: compile through
# ccache when it is installed (it is not one of deps.sh's packages; set
# ICPBENCH_CCACHE=0 to compile without it). Paths are hashed relative to the
# repository, so another clone of the same revision reuses the objects.
ccache_args=()
if [ "${ICPBENCH_CCACHE:-1}" != 0 ] && command -v ccache >/dev/null 2>&1; then
  export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
  ccache_args=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
else
  ccache_args=(-DCMAKE_CXX_COMPILER_LAUNCHER=)
fi
