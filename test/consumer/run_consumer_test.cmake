# Copyright (c) 2026 the Graphcut_remeshing developers.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# cmake -P script run by the CTest test `installed_package_consumer`: installs the package's build
# tree into a fresh prefix, checks what was installed, then configures, builds and runs the
# consumer project of this directory against that prefix only.
#
# Variables (-D): BUILD_TREE, BUILD_CONFIG, INSTALL_CMAKEDIR, SOURCE_DIR, WORK_DIR, GENERATOR,
# BUILD_TYPE, CXX_COMPILER and, optionally, COMPILER_LAUNCHER.

foreach(variable BUILD_TREE INSTALL_CMAKEDIR SOURCE_DIR WORK_DIR GENERATOR BUILD_TYPE CXX_COMPILER)
  if(NOT DEFINED ${variable} OR "${${variable}}" STREQUAL "")
    message(FATAL_ERROR "run_consumer_test.cmake: ${variable} is not set")
  endif()
endforeach()

set(prefix "${WORK_DIR}/prefix")
set(consumer_build "${WORK_DIR}/build")
# From scratch each time: a stale prefix or cache would hide a broken installation.
file(REMOVE_RECURSE "${prefix}" "${consumer_build}")

# 1. Install, as a user would.
set(config_arguments)
if(DEFINED BUILD_CONFIG AND NOT "${BUILD_CONFIG}" STREQUAL "")
  set(config_arguments --config "${BUILD_CONFIG}")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_TREE}" --prefix "${prefix}" ${config_arguments}
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${result}):\n${output}")
endif()
message(STATUS "Installed into ${prefix}")

# 2. What must be there, and what must not.
set(package_dir "${prefix}/${INSTALL_CMAKEDIR}")
foreach(file
    "${prefix}/include/CGAL/Polygon_mesh_processing/graphcut_isotropic_remeshing.h"
    "${prefix}/include/CGAL/Polygon_mesh_processing/graphcut_remeshing_parameters.h"
    "${prefix}/include/CGAL/Polygon_mesh_processing/mesh_quality_report.h"
    "${prefix}/include/CGAL/Polygon_mesh_processing/internal/Graphcut_remeshing/remesher.h"
    "${package_dir}/CGAL_Graphcut_remeshingConfig.cmake"
    "${package_dir}/CGAL_Graphcut_remeshingConfigVersion.cmake"
    "${package_dir}/CGAL_Graphcut_remeshingTargets.cmake")
  if(NOT EXISTS "${file}")
    message(FATAL_ERROR "Not installed: ${file}")
  endif()
endforeach()
file(READ "${package_dir}/CGAL_Graphcut_remeshingTargets.cmake" targets)
if(targets MATCHES "graphcut_remeshing_warnings")
  message(FATAL_ERROR "The exported targets name the internal graphcut_remeshing_warnings target")
endif()
if(NOT targets MATCHES "add_library\\(CGAL::Graphcut_remeshing INTERFACE IMPORTED\\)")
  message(FATAL_ERROR "The exported targets do not define CGAL::Graphcut_remeshing")
endif()
file(GLOB tools "${prefix}/bin/*")
message(STATUS "Installed tools: ${tools}")

# 3. Configure and build the consumer against the prefix alone (no package registry).
set(launcher_argument)
if(DEFINED COMPILER_LAUNCHER AND NOT "${COMPILER_LAUNCHER}" STREQUAL "")
  set(launcher_argument "-DCMAKE_CXX_COMPILER_LAUNCHER=${COMPILER_LAUNCHER}")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${consumer_build}" -G "${GENERATOR}"
                        "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}"
                        "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}"
                        ${launcher_argument}
                        "-DCMAKE_PREFIX_PATH=${prefix}"
                        -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
                        "-DGRAPHCUT_REMESHING_EXPECTED_PREFIX=${prefix}"
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "Configuring the consumer failed (${result})")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" --build "${consumer_build}" --config "${BUILD_TYPE}"
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "Building the consumer failed (${result})")
endif()

# 4. Run it (multi-configuration generators put it in a subdirectory).
set(program "${consumer_build}/graphcut_remeshing_consumer")
if(NOT EXISTS "${program}")
  set(program "${consumer_build}/${BUILD_TYPE}/graphcut_remeshing_consumer")
endif()
execute_process(COMMAND "${program}" RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "The consumer failed (${result})")
endif()
