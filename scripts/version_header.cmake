# Writes OUT, the version header (IN with @PROJECT_VERSION@ and @YDRY_COMMIT@, the commit of
# SOURCE_DIR as `git describe --always --dirty` gives it), and touches it only when its text
# changes. CMakeLists.txt runs it at every build, so that --version and summary.json name the
# commit a binary was built from, not the one CMake last configured at.
#   cmake -DSOURCE_DIR=... -DIN=... -DOUT=... -DPROJECT_VERSION=... -P version_header.cmake
execute_process(COMMAND git describe --always --dirty --abbrev=12
                WORKING_DIRECTORY ${SOURCE_DIR} OUTPUT_VARIABLE YDRY_COMMIT
                OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT YDRY_COMMIT)
  set(YDRY_COMMIT "unknown")
endif()
configure_file(${IN} ${OUT}.new @ONLY)
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different ${OUT}.new ${OUT})
file(REMOVE ${OUT}.new)
