# Script mode (cmake -P), run as the last step of every complete build (target
# tamias_build_stamp, which depends on every other target): writes OUT_DIR/provenance.json, what
# the build is of, for the traceability harness and the verification programs (docs/
# traceability.md, "Provenance"). Inputs: SOURCE_DIR, OUT_DIR, COMPILER, FLAGS, OPTIONS, PACKAGES.
#   commit   git HEAD
#   dirty    whether tracked files differ from HEAD
#   tree     SHA-1 of the commit, `git status --porcelain --untracked-files=no` and
#            `git diff HEAD`: the sources the build was made from (traceability/builds.py
#            computes the same key for the checkout it reports)
#   build_id the first 16 hex digits of SHA-1 over the tree, compiler, flags, options and the
#            Debian packages' versions: the same sources built the same way get the same id
#   built    UTC time this build id was first stamped
# Written last, it describes a build that completed; a source changed since, or a target built
# alone since, shows as a different tree or as work `ninja -n` still has to do.
find_package(Git QUIET)
set(commit "unknown")
set(changes "")
if(GIT_EXECUTABLE)
  execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR} rev-parse HEAD
                  OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE
                  RESULT_VARIABLE rc ERROR_QUIET)
  if(NOT rc EQUAL 0)
    set(commit "unknown")
  endif()
  execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR} status --porcelain
                          --untracked-files=no
                  OUTPUT_VARIABLE status ERROR_QUIET)
  execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR} diff HEAD
                  OUTPUT_VARIABLE diff ERROR_QUIET)
  set(changes "${status}${diff}")
endif()
if(changes STREQUAL "")
  set(dirty false)
else()
  set(dirty true)
endif()
string(SHA1 tree "${commit}\n${changes}")

# The Debian packages the build and its evidence depend on, with their versions.
set(package_json "")
set(package_text "")
foreach(p IN LISTS PACKAGES)
  execute_process(COMMAND dpkg-query -W -f=\${Version} ${p}
                  OUTPUT_VARIABLE version RESULT_VARIABLE rc ERROR_QUIET)
  if(NOT rc EQUAL 0 OR version STREQUAL "")
    set(version "not installed")
  endif()
  string(APPEND package_text "${p}=${version}\n")
  if(NOT package_json STREQUAL "")
    string(APPEND package_json ", ")
  endif()
  string(APPEND package_json "\"${p}\": \"${version}\"")
endforeach()

string(SHA1 id "${tree}\n${COMPILER}\n${FLAGS}\n${OPTIONS}\n${package_text}")
string(SUBSTRING "${id}" 0 16 build_id)

set(out ${OUT_DIR}/provenance.json)
set(built "")
if(EXISTS ${out})
  file(READ ${out} old)
  if(old MATCHES "\"build_id\": \"${build_id}\"" AND old MATCHES "\"built\": \"([^\"]*)\"")
    set(built "${CMAKE_MATCH_1}")
  endif()
endif()
if(built STREQUAL "")
  string(TIMESTAMP built "%Y-%m-%dT%H:%M:%SZ" UTC)
endif()

# JSON strings: escape backslashes and quotes of the flags.
foreach(v COMPILER FLAGS OPTIONS)
  string(REPLACE "\\" "\\\\" ${v}_json "${${v}}")
  string(REPLACE "\"" "\\\"" ${v}_json "${${v}_json}")
endforeach()
file(WRITE ${out}.tmp
"{\"commit\": \"${commit}\", \"dirty\": ${dirty}, \"tree\": \"${tree}\",
 \"build_id\": \"${build_id}\", \"built\": \"${built}\",
 \"compiler\": \"${COMPILER_json}\", \"flags\": \"${FLAGS_json}\", \"options\": \"${OPTIONS_json}\",
 \"packages\": {${package_json}}}
")
file(RENAME ${out}.tmp ${out})
