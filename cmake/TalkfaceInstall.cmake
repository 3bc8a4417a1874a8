# Install rules, the exported CMake package (find_package(talkface)) and the pkg-config files.
include(CMakePackageConfigHelpers)

set(TALKFACE_CMAKE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/talkface")

set(TALKFACE_INSTALLED_LIBRARIES libtalkface libtalkface_c)
set(TALKFACE_PC_NAMES talkface talkface_c)
if(TARGET libtalkface_photo)
  list(APPEND TALKFACE_INSTALLED_LIBRARIES libtalkface_photo)
  list(APPEND TALKFACE_PC_NAMES talkface_photo)
endif()
install(TARGETS ${TALKFACE_INSTALLED_LIBRARIES}
  EXPORT talkfaceTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# The photo stage's headers only with its library.
install(DIRECTORY "${PROJECT_SOURCE_DIR}/include/talkface" DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        PATTERN face_from_photo.hpp EXCLUDE PATTERN talkface_photo.h EXCLUDE)
if(TARGET libtalkface_photo)
  install(FILES "${PROJECT_SOURCE_DIR}/include/talkface/face_from_photo.hpp"
                "${PROJECT_SOURCE_DIR}/include/talkface/talkface_photo.h"
                "${PROJECT_BINARY_DIR}/include/talkface/photo_export.h"
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/talkface)
endif()
install(FILES "${PROJECT_BINARY_DIR}/include/talkface/version.h"
              "${PROJECT_BINARY_DIR}/include/talkface/export.h"
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/talkface)

install(EXPORT talkfaceTargets NAMESPACE talkface:: DESTINATION ${TALKFACE_CMAKE_DIR})
configure_package_config_file("${PROJECT_SOURCE_DIR}/cmake/talkfaceConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/talkfaceConfig.cmake" INSTALL_DESTINATION ${TALKFACE_CMAKE_DIR})
# SameMinorVersion while 0.x (any minor release may break the API), SameMajorVersion from 1.0.
write_basic_package_version_file("${PROJECT_BINARY_DIR}/talkfaceConfigVersion.cmake"
  COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/talkfaceConfig.cmake" "${PROJECT_BINARY_DIR}/talkfaceConfigVersion.cmake"
        DESTINATION ${TALKFACE_CMAKE_DIR})

# The pc files find the prefix from their own folder: CMAKE_INSTALL_PREFIX at configure time is not
# where `cmake --install --prefix DIR` puts them.
file(RELATIVE_PATH TALKFACE_PC_PREFIX_FROM_PCFILEDIR "/prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/prefix")
string(REGEX REPLACE "/$" "" TALKFACE_PC_PREFIX_FROM_PCFILEDIR "${TALKFACE_PC_PREFIX_FROM_PCFILEDIR}")
foreach(pc_name ${TALKFACE_PC_NAMES})
  configure_file("${PROJECT_SOURCE_DIR}/cmake/${pc_name}.pc.in" "${PROJECT_BINARY_DIR}/${pc_name}.pc" @ONLY)
  install(FILES "${PROJECT_BINARY_DIR}/${pc_name}.pc" DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
endforeach()
