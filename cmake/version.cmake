# The project version (project(pflip VERSION ...)) is the only place the version is written;
# this file derives the rest from it.

# pf/pf_version.h: PF_VERSION_* for the header, pf_version() and the installed package.
set(PF_GENERATED_INCLUDE_DIR "${PROJECT_BINARY_DIR}/include")
configure_file("${CMAKE_CURRENT_LIST_DIR}/templates/pf_version.h.in"
               "${PF_GENERATED_INCLUDE_DIR}/pf/pf_version.h" @ONLY)
# What #include <pf/pf.h> needs in the build tree: the written headers and the generated one.
set(PF_PUBLIC_INCLUDE_DIRS "${PROJECT_SOURCE_DIR}/include" "${PF_GENERATED_INCLUDE_DIR}")

# SOVERSION follows the ABI. From 1.0 on, only a major release may break it: SOVERSION = major.
# Before 1.0 every minor release may break it (pf_sim_desc and pf_stats still grow), so the
# soname carries the minor too, "0.minor": libpflip.so.0.1 and libpflip.so.0.2 are different
# ABIs and a loader never mixes them up; patch releases keep the soname.
# pflipConfigVersion.cmake applies the same rule (cmake/install.cmake).
if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(PF_SOVERSION "0.${PROJECT_VERSION_MINOR}")
  set(PF_VERSION_COMPATIBILITY SameMinorVersion)
else()
  set(PF_SOVERSION "${PROJECT_VERSION_MAJOR}")
  set(PF_VERSION_COMPATIBILITY SameMajorVersion)
endif()
