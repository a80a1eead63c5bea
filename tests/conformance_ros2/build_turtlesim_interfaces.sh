#!/usr/bin/env bash
# Builds turtlesim's interfaces (tests/sim/turtlesim_ros2_interfaces: the fields `ros2 interface show` prints) for
# real rclpy with Jazzy's rosidl wheels, through tests/interfaces/build_real_interfaces.sh, into BUILD (never into the
# repository); real_turtlesim2.py and the turtlesim probes then import turtlesim.msg/srv/action from BUILD/install.
#   build_turtlesim_interfaces.sh <build venv> <build folder>
set -euo pipefail
HERE="$(cd "$(dirname "$0")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
VENV="$1"; BUILD="$2"
SRC="$BUILD/src/turtlesim"
mkdir -p "$SRC"
cp -r "$ROOT/tests/sim/turtlesim_ros2_interfaces/turtlesim/." "$SRC/"
cat > "$SRC/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.8)
project(turtlesim)
find_package(ament_cmake REQUIRED)
find_package(rosidl_default_generators REQUIRED)
find_package(action_msgs REQUIRED)
rosidl_generate_interfaces(${PROJECT_NAME}
  "msg/Color.msg" "msg/Pose.msg"
  "srv/Kill.srv" "srv/SetPen.srv" "srv/Spawn.srv" "srv/TeleportAbsolute.srv" "srv/TeleportRelative.srv"
  "action/RotateAbsolute.action"
  DEPENDENCIES action_msgs)
ament_export_dependencies(rosidl_default_runtime)
ament_package()
CMAKE
exec "$ROOT/tests/interfaces/build_real_interfaces.sh" "$SRC" "$VENV" "$BUILD/build"
