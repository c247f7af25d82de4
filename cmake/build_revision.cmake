# Writes OUT, a header defining ICPBENCH_BUILD_REVISION: the source tree's
# revision (git describe --dirty) when the binary is built. Run at every
# build by the build_revision target; the header is rewritten only when the
# revision changes, so a new commit recompiles one file.
execute_process(
  COMMAND git -C "${SOURCE_DIR}" describe --always --dirty --abbrev=12
  OUTPUT_VARIABLE revision
  OUTPUT_STRIP_TRAILING_WHITESPACE
  ERROR_QUIET
  RESULT_VARIABLE status)
if(NOT status EQUAL 0 OR revision STREQUAL "")
  set(revision "unknown")  # not a git checkout (a tarball), or no git
endif()
set(text "#define ICPBENCH_BUILD_REVISION \"${revision}\"\n")
set(old "")
if(EXISTS "${OUT}")
  file(READ "${OUT}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUT}" "${text}")
endif()
