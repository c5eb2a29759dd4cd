# Install rules: both libraries, the public headers, a CMake package (pflip::pflip shared,
# pflip::pflip_static) and pflip.pc for pkg-config. Included from the top-level CMakeLists.txt
# when PF_INSTALL is on (the default when pflip is the top-level project).
include(CMakePackageConfigHelpers)

set(PF_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/pflip" CACHE STRING
    "Where pflipConfig.cmake is installed, relative to the prefix")

install(TARGETS pflip pflip_static EXPORT pflipTargets
        RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}"
        LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}"
        ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}")
install(FILES "${PROJECT_SOURCE_DIR}/include/pf/pf.h" "${PF_GENERATED_INCLUDE_DIR}/pf/pf_version.h"
        DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/pf")

install(EXPORT pflipTargets NAMESPACE pflip:: DESTINATION "${PF_INSTALL_CMAKEDIR}")
configure_package_config_file("${CMAKE_CURRENT_LIST_DIR}/templates/pflipConfig.cmake.in"
                              "${PROJECT_BINARY_DIR}/package/pflipConfig.cmake"
                              INSTALL_DESTINATION "${PF_INSTALL_CMAKEDIR}")
# PF_VERSION_COMPATIBILITY (cmake/version.cmake): SameMinorVersion before 1.0, where a minor
# release may break the ABI, SameMajorVersion after; the same rule as the SOVERSION.
write_basic_package_version_file("${PROJECT_BINARY_DIR}/package/pflipConfigVersion.cmake"
                                 COMPATIBILITY ${PF_VERSION_COMPATIBILITY})
install(FILES "${PROJECT_BINARY_DIR}/package/pflipConfig.cmake"
              "${PROJECT_BINARY_DIR}/package/pflipConfigVersion.cmake"
        DESTINATION "${PF_INSTALL_CMAKEDIR}")

# pflip.pc finds the prefix from its own location (${pcfiledir}), so a tree installed with
# `cmake --install --prefix DIR` or moved elsewhere still works.
set(PF_PC_DIR "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  set(PF_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
else()
  file(RELATIVE_PATH PF_PC_UP "/prefix/${PF_PC_DIR}" "/prefix")
  string(REGEX REPLACE "/$" "" PF_PC_UP "${PF_PC_UP}")
  set(PF_PC_PREFIX "\${pcfiledir}/${PF_PC_UP}")
endif()
foreach(dir LIBDIR INCLUDEDIR)
  if(IS_ABSOLUTE "${CMAKE_INSTALL_${dir}}")
    set(PF_PC_${dir} "${CMAKE_INSTALL_${dir}}")
  else()
    set(PF_PC_${dir} "\${prefix}/${CMAKE_INSTALL_${dir}}")
  endif()
endforeach()
configure_file("${CMAKE_CURRENT_LIST_DIR}/templates/pflip.pc.in" "${PROJECT_BINARY_DIR}/package/pflip.pc" @ONLY)
install(FILES "${PROJECT_BINARY_DIR}/package/pflip.pc" DESTINATION "${PF_PC_DIR}")
