# Writes commit.hpp with the source tree's commit (`git describe --always --dirty`, "unknown"
# outside a git checkout), rewriting it only when the commit changed so builds stay incremental.
# Run at every build by the feedflow_commit target (models/CMakeLists.txt).
execute_process(COMMAND git -C ${SOURCE_DIR} describe --always --dirty --abbrev=10
                OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE failed)
if(failed OR commit STREQUAL "")
  set(commit "unknown")
endif()
set(text "#pragma once\n// Generated at build time by models/core/write_commit.cmake.\nnamespace feedflow {\ninline constexpr const char* kCommit = \"${commit}\";\n}  // namespace feedflow\n")
if(EXISTS ${OUTPUT})
  file(READ ${OUTPUT} old)
endif()
if(NOT old STREQUAL text)
  file(WRITE ${OUTPUT} "${text}")
endif()
