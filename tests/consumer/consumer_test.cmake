# CTest driver of the consumer tests (tests/CMakeLists.txt registers one test per MODE):
#   install       cmake --install the already-built tree BUILD_DIR into PREFIX
#   find_package  tests/consumer as a project with find_package(pflip) from PREFIX; runs
#                 pflip_consumer (shared) and pflip_consumer_static
#   pkg_config    cc consumer.c $(pkg-config --cflags --libs pflip egl) against PREFIX; runs it
#   subdirectory  tests/consumer as a project with add_subdirectory(SOURCE_DIR); runs it
#   snippets      every C and find_package block of README.md and docs/integration.md, as
#                 written (tests/consumer/snippets.py), compiled against PREFIX
# Every step fails the test on a non-zero exit status. Arguments: -DMODE= -DSOURCE_DIR=
# -DBUILD_DIR= -DPREFIX= -DWORK= -DGENERATOR= -DC_COMPILER= -DPYTHON= -DVERSION=
set(here "${CMAKE_CURRENT_LIST_DIR}")

function(run)
  execute_process(COMMAND ${ARGN} COMMAND_ECHO STDOUT COMMAND_ERROR_IS_FATAL ANY)
endfunction()

# Configures and builds tests/consumer into WORK/<MODE> with the extra cache arguments.
function(build_consumer)
  set(dir "${WORK}/${MODE}")
  file(REMOVE_RECURSE "${dir}")
  # No package registry: only PREFIX may satisfy find_package(pflip).
  run(${CMAKE_COMMAND} -S "${here}" -B "${dir}" -G "${GENERATOR}" "-DCMAKE_C_COMPILER=${C_COMPILER}"
      -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF ${ARGN})
  run(${CMAKE_COMMAND} --build "${dir}")
endfunction()

if(MODE STREQUAL "install")
  file(REMOVE_RECURSE "${PREFIX}")
  run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${PREFIX}")
elseif(MODE STREQUAL "find_package")
  build_consumer("-DCMAKE_PREFIX_PATH=${PREFIX}" -DPF_CONSUMER_MODE=package "-DPF_EXPECTED_VERSION=${VERSION}")
  run("${WORK}/${MODE}/pflip_consumer")
  run("${WORK}/${MODE}/pflip_consumer_static")
elseif(MODE STREQUAL "pkg_config")
  file(GLOB_RECURSE pc "${PREFIX}/pflip.pc")
  if(NOT pc)
    message(FATAL_ERROR "no pflip.pc under ${PREFIX}")
  endif()
  get_filename_component(pc_dir "${pc}" DIRECTORY)
  set(ENV{PKG_CONFIG_PATH} "${pc_dir}")
  execute_process(COMMAND pkg-config --cflags --libs pflip egl OUTPUT_VARIABLE flags
                  OUTPUT_STRIP_TRAILING_WHITESPACE COMMAND_ERROR_IS_FATAL ANY)
  execute_process(COMMAND pkg-config --variable=libdir pflip OUTPUT_VARIABLE libdir
                  OUTPUT_STRIP_TRAILING_WHITESPACE COMMAND_ERROR_IS_FATAL ANY)
  separate_arguments(flags UNIX_COMMAND "${flags}")
  file(MAKE_DIRECTORY "${WORK}/${MODE}")
  set(exe "${WORK}/${MODE}/pflip_consumer")
  # The rpath stands in for the engine's own deployment (or LD_LIBRARY_PATH).
  run("${C_COMPILER}" -std=c99 -Wall -Werror "${here}/consumer.c" -o "${exe}" ${flags} -lm "-Wl,-rpath,${libdir}")
  run("${exe}")
elseif(MODE STREQUAL "subdirectory")
  build_consumer(-DPF_CONSUMER_MODE=subdirectory "-DPFLIP_SOURCE_DIR=${SOURCE_DIR}"
                 "-DPython3_EXECUTABLE=${PYTHON}")
  run("${WORK}/${MODE}/pflip_consumer")
elseif(MODE STREQUAL "snippets")
  set(dir "${WORK}/${MODE}")
  file(REMOVE_RECURSE "${dir}")
  execute_process(COMMAND "${PYTHON}" "${here}/snippets.py" "${dir}" README.md docs/integration.md
                  WORKING_DIRECTORY "${SOURCE_DIR}" OUTPUT_VARIABLE written OUTPUT_STRIP_TRAILING_WHITESPACE
                  COMMAND_ERROR_IS_FATAL ANY)
  string(REPLACE "\n" ";" written "${written}")
  list(LENGTH written count)
  if(count LESS 3)
    message(FATAL_ERROR "snippets.py found ${count} snippets, expected the README's and integration.md's")
  endif()
  foreach(snippet IN LISTS written)
    if(snippet MATCHES "[.]c$")
      # Strict C99 as an engine's C code may be; a call to something pf.h does not declare fails.
      run("${C_COMPILER}" -std=c99 -pedantic-errors -Wall -Werror -c "${snippet}" -o "${snippet}.o"
          "-I${PREFIX}/include")
    else()
      run(${CMAKE_COMMAND} -S "${snippet}" -B "${snippet}/build" -G "${GENERATOR}" "-DCMAKE_C_COMPILER=${C_COMPILER}"
          -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF "-DCMAKE_PREFIX_PATH=${PREFIX}")
      run(${CMAKE_COMMAND} --build "${snippet}/build")
    endif()
  endforeach()
else()
  message(FATAL_ERROR "MODE: expected install, find_package, pkg_config, subdirectory or snippets, got '${MODE}'")
endif()
