# SPDX-License-Identifier: MIT
# `cmake --install`: libo3d (with its SONAME link), the C headers, the header-only C++ wrapper, a CMake
# package (find_package(o3d) -> o3d::o3d for C, o3d::o3dpp for C++) and a relocatable pkg-config file.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS o3d EXPORT o3dTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# The reconstruction program finds libo3d beside it, in ../lib, wherever the prefix is moved.
set_target_properties(o3d_reconstruction PROPERTIES INSTALL_RPATH "$ORIGIN/../${CMAKE_INSTALL_LIBDIR}")
install(TARGETS o3d_reconstruction RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/capi/include/o3d DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.h")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/bindings/cpp/include/o3dpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.hpp")

set(O3D_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/o3d)
install(EXPORT o3dTargets NAMESPACE o3d:: DESTINATION ${O3D_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/o3dConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/o3dConfig.cmake INSTALL_DESTINATION ${O3D_CMAKE_DIR})
# 0.x: a minor version may break the ABI (docs/conventions.md), so only the same minor is compatible.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/o3dConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/o3dConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/o3dConfigVersion.cmake
  DESTINATION ${O3D_CMAKE_DIR})

configure_file(${PROJECT_SOURCE_DIR}/cmake/o3d.pc.in ${CMAKE_CURRENT_BINARY_DIR}/o3d.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/o3d.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
