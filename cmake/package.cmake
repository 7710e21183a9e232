# `cpack -G DEB` in the build directory: billiard_<version>_<arch>.deb of what cmake/install.cmake
# installs, under /usr. It is a development package (headers, static libraries, the CMake package)
# that also runs (the binaries), so it depends on the -dev packages of everything the CMake
# package finds; each is one launch_scripts/setup.sh installs (tests/install_test.sh checks).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME billiard)
set(CPACK_PACKAGE_VENDOR "billiard")
set(CPACK_PACKAGE_CONTACT "billiard maintainers <billiard@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "Robot billiard controller: ball physics, shot planner, vision estimator over LCM")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION devel)
# The package's dependencies, from setup.sh's list: what the CMake package finds (Eigen, Ceres,
# OpenCV, libjpeg-turbo, LCM and the GLib its pkg-config file needs, nlohmann-json),
# pkg-config, with which it finds LCM, and cpp-httplib, whose library viewer_node runs with.
set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "libeigen3-dev, libceres-dev, libopencv-dev, libjpeg62-turbo-dev, liblcm-dev, libglib2.0-dev, nlohmann-json3-dev, pkg-config, libcpp-httplib-dev")
# What the launch scripts and the Java message types run with: lcm-logger, python3 for the
# loop's table, iproute2 for its network namespace, socat for its live view out of it, LCM's jar.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "liblcm-bin, liblcm-java, python3, iproute2, socat")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "default-jre")
include(CPack)
