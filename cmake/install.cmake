# What `cmake --install build --prefix P` puts under P, and the CMake package, the pkg-config files
# and the .deb made of it (docs/installing.md says how a user consumes them):
#
#   bin/                              billiard, planner_node, estimator_node, table_sim_node,
#                                     camera_node, viewer_node
#   lib/libbilliard_*.a               the libraries, static as they are built (lib/ is
#                                     GNUInstallDirs' LIBDIR: lib/<multiarch>/ in a build
#                                     configured with CMAKE_INSTALL_PREFIX=/usr)
#   include/billiard/...              the public headers: each at its repository path under
#                                     billiard/, its includes rewritten to match, so that a
#                                     user's own sim/ or planner/ cannot shadow ours
#   lib/cmake/billiard/               the package: billiard::<target>, found by component
#   lib/pkgconfig/                    billiard-physics.pc (Eigen alone), billiard.pc (all)
#   share/billiard/params/            the parameter sets and tables/ (also compiled into the
#                                     libraries: the installed files are for reading and as
#                                     templates of --params FILE.json)
#   share/billiard/lcmtypes/          the .lcm definitions
#   share/java/billiard_lcmtypes.jar  the Java message types
#   share/billiard/launch_scripts/    the scripts that run installed binaries
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(BILLIARD_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/billiard)

# The components, bottom up: each an export set of targets with the folders of their headers and
# the packages it needs besides the components before it (cmake/billiardConfig.cmake.in finds
# them).
set(BILLIARD_COMPONENTS physics params planner estimator lcmtypes)
set(billiard_physics_targets physics batch table cue)
set(billiard_physics_headers sim/physics sim/batch sim/table sim/cue)
set(billiard_params_targets params camera model_choice)
set(billiard_params_headers sim/params sim/camera sim/model_choice)
set(billiard_planner_targets planner pot)
set(billiard_planner_headers planner planner/pot)
set(billiard_estimator_targets ball_class assignment ball_tracker ball_detector ball_estimator render)
set(billiard_estimator_headers estimator sim/render)
set(billiard_lcmtypes_targets lcmtypes message_checks image_codec)
set(billiard_lcmtypes_headers lcmtypes)
# Headers that stay in the tree: the 5-DOF right-hand side and the rest model (the integrators'
# insides, whose automatic differentiation needs Ceres' Jet: a physics user needs Eigen alone)
# and the reliability report's edge cases (its library is not installed).
set(BILLIARD_PRIVATE_HEADERS sim/physics/ball_dynamics.h sim/physics/rest.h
                             planner/edge_report.h)
# billiard::estimator is the whole estimator (frames to ball states), as a user names it.
set_target_properties(ball_estimator PROPERTIES EXPORT_NAME estimator)

foreach(component ${BILLIARD_COMPONENTS})
  foreach(target ${billiard_${component}_targets})
    get_target_property(type ${target} TYPE)
    target_include_directories(${target} INTERFACE
                               $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
    if(NOT type STREQUAL "INTERFACE_LIBRARY")
      # libbilliard_physics.a, not a libphysics.a among the system's libraries.
      get_target_property(export_name ${target} EXPORT_NAME)
      if(NOT export_name)
        set(export_name ${target})
      endif()
      set_target_properties(${target} PROPERTIES OUTPUT_NAME billiard_${export_name})
    endif()
  endforeach()
  install(TARGETS ${billiard_${component}_targets} EXPORT billiard-${component}
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT library)
  install(EXPORT billiard-${component} NAMESPACE billiard:: DESTINATION ${BILLIARD_CMAKE_DIR}
          FILE billiard-${component}-targets.cmake COMPONENT library)

  set(headers)
  foreach(folder ${billiard_${component}_headers})
    file(GLOB folder_headers RELATIVE ${PROJECT_SOURCE_DIR} CONFIGURE_DEPENDS
         ${PROJECT_SOURCE_DIR}/${folder}/*.h)
    list(APPEND headers ${folder_headers})
  endforeach()
  list(REMOVE_ITEM headers ${BILLIARD_PRIVATE_HEADERS})
  set(BILLIARD_INSTALLED_HEADERS ${BILLIARD_INSTALLED_HEADERS} ${headers})
endforeach()

# The generated message headers and the version, at their include paths under the build tree.
file(GLOB lcm_definitions CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/lcmtypes/*.lcm)
set(generated_headers lcmtypes/version.h)
foreach(definition ${lcm_definitions})
  get_filename_component(type_name ${definition} NAME_WE)
  list(APPEND generated_headers lcmtypes/billiard/${type_name}.hpp)
endforeach()

# Each header is copied with its project includes ("sim/...", "lcmtypes/...") prefixed by
# billiard/, at install time (cmake/install_headers.cmake) so that the copies are always of the
# tree as built.
set(header_entries)
foreach(header ${BILLIARD_INSTALLED_HEADERS})
  list(APPEND header_entries "${PROJECT_SOURCE_DIR}|${header}")
endforeach()
foreach(header ${generated_headers})
  list(APPEND header_entries "${LCMTYPES_GENERATED_ROOT}|${header}")
endforeach()
file(WRITE ${PROJECT_BINARY_DIR}/installed_headers.cmake
     "set(BILLIARD_HEADER_ENTRIES \"${header_entries}\")\n"
     "set(BILLIARD_INCLUDE_DIR \"${CMAKE_INSTALL_INCLUDEDIR}\")\n")
install(CODE "include(\"${PROJECT_BINARY_DIR}/installed_headers.cmake\")
              include(\"${PROJECT_SOURCE_DIR}/cmake/install_headers.cmake\")"
        COMPONENT library)

install(TARGETS billiard planner_node estimator_node table_sim_node camera_node viewer_node
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT library)

set(BILLIARD_DATA_DIR ${CMAKE_INSTALL_DATADIR}/billiard)
file(GLOB parameter_sets CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/sim/params/*.json)
file(GLOB table_specs CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/sim/params/tables/*.json)
install(FILES ${parameter_sets} DESTINATION ${BILLIARD_DATA_DIR}/params COMPONENT library)
install(FILES ${table_specs} DESTINATION ${BILLIARD_DATA_DIR}/params/tables COMPONENT library)
install(FILES ${lcm_definitions} DESTINATION ${BILLIARD_DATA_DIR}/lcmtypes COMPONENT library)
install(FILES ${LCMTYPES_JAVA_JAR} DESTINATION ${CMAKE_INSTALL_DATADIR}/java COMPONENT library)

# The scripts that run installed binaries (script_support.sh's bin_dir): the closed loop and the
# replay, with what they source.
set(script_dir ${PROJECT_SOURCE_DIR}/launch_scripts)
install(PROGRAMS ${script_dir}/run_loop.sh ${script_dir}/replay.sh
        DESTINATION ${BILLIARD_DATA_DIR}/launch_scripts COMPONENT library)
install(FILES ${script_dir}/script_support.sh ${script_dir}/lcm_network.sh
              ${script_dir}/camera_mode.sh
        DESTINATION ${BILLIARD_DATA_DIR}/launch_scripts COMPONENT library)

# The package: the config finds each asked-for component's dependencies, then its targets.
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/billiardConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/billiardConfig.cmake
                              INSTALL_DESTINATION ${BILLIARD_CMAKE_DIR}
                              PATH_VARS CMAKE_INSTALL_DATADIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/billiardConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/billiardConfig.cmake
              ${PROJECT_BINARY_DIR}/billiardConfigVersion.cmake
        DESTINATION ${BILLIARD_CMAKE_DIR} COMPONENT library)

# pkg-config: the physics alone (Eigen), and everything. Their prefix is the one they are found
# under (pkg-config's ${pcfiledir}), as the CMake package's is, so that any --prefix works.
file(RELATIVE_PATH pc_to_prefix /${CMAKE_INSTALL_LIBDIR}/pkgconfig /)
set(BILLIARD_PC_PREFIX "\${pcfiledir}/${pc_to_prefix}")
foreach(pc billiard-physics billiard)
  configure_file(${PROJECT_SOURCE_DIR}/cmake/${pc}.pc.in ${PROJECT_BINARY_DIR}/${pc}.pc @ONLY)
  install(FILES ${PROJECT_BINARY_DIR}/${pc}.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig
          COMPONENT library)
endforeach()
