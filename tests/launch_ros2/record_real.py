"""Record what real ROS 2 Jazzy launch starts for each case in cases/runs.json (run where real launch is installed).

``python record_real.py LAUNCH_SHARE`` under an interpreter that imports real launch, launch_xml, launch_yaml,
launch_ros and rclpy (Jazzy); LAUNCH_SHARE is that install's share/launch folder (launch_xml reads its substitution
grammar from there). It installs nothing and fetches nothing: the case package is laid out as colcon would install
it in a temporary prefix, with stand-in executables, and each case runs through launch's own LaunchService as
`ros2 launch` runs it. A handler on every process start records its argv and the parameter files it is handed;
errors are what launch logs. Also records what `ros2 launch --show-args` prints for each file. Writes
cases/real_records.json.
"""
from __future__ import annotations

import json
import logging
import os
import shutil
import stat
import sys
import tempfile
import types
from pathlib import Path

HERE = Path(__file__).resolve().parent
CASES = HERE / "cases"
PACKAGE = CASES / "ws" / "course_pkg"
EXECUTABLES = {"course_pkg": ["mover", "square", "follower", "beacon_search", "figure_of_eight", "waypoints",
                              "wall_follower", "talker", "listener"],
               "turtlesim": ["turtlesim_node", "mimic", "turtle_teleop_key", "draw_square"],
               "rviz2": ["rviz2"]}


def install(prefix: Path, launch_share: Path) -> None:
    """The case package and the world's packages as colcon would install them, with stand-in executables."""
    index = prefix / "share" / "ament_index" / "resource_index" / "packages"
    index.mkdir(parents=True)
    (index / "launch").write_text("")
    shutil.copytree(launch_share, prefix / "share" / "launch")
    for package, names in EXECUTABLES.items():
        (index / package).write_text("")
        share = prefix / "share" / package
        if package == "course_pkg":
            for folder in ("launch", "config"):
                shutil.copytree(PACKAGE / folder, share / folder)
        share.mkdir(parents=True, exist_ok=True)
        lib = prefix / "lib" / package
        lib.mkdir(parents=True)
        for name in names:
            (lib / name).write_text("#!/bin/sh\nexit 0\n")
            (lib / name).chmod(stat.S_IRWXU)
    # The ros2 command line the tutorials' ExecuteProcess actions call: a stand-in that exits at once, so that the
    # handlers of its start and exit run as they would.
    (prefix / "bin").mkdir()
    (prefix / "bin" / "ros2").write_text("#!/bin/sh\nexit 0\n")
    (prefix / "bin" / "ros2").chmod(stat.S_IRWXU)


def record(case: dict, prefix: Path) -> dict:
    import launch
    from launch.actions import IncludeLaunchDescription, RegisterEventHandler
    from launch.event_handlers import OnProcessStart
    from launch.launch_description_sources import AnyLaunchDescriptionSource

    started: list[dict] = []
    logs: list[str] = []

    def on_start(event, context):
        cmd = list(event.cmd)
        files = []
        for index, word in enumerate(cmd[:-1]):
            if word == "--params-file":
                files.append(Path(cmd[index + 1]).read_text())
        started.append({"name": event.process_name, "cmd": cmd, "params_files": files})

    class Catch(logging.Handler):
        def emit(self, record: logging.LogRecord) -> None:
            logs.append(record.getMessage())

    handler = Catch()
    loggers = [logging.getLogger(), logging.getLogger("launch"), logging.getLogger("launch.user")]
    for logger in loggers:
        logger.addHandler(handler)
    service = launch.LaunchService(argv=[f"{k}:={v}" for k, v in case["args"].items()])
    path = prefix / "share" / "course_pkg" / "launch" / case["file"]
    service.include_launch_description(launch.LaunchDescription([
        RegisterEventHandler(OnProcessStart(on_start=on_start)),
        IncludeLaunchDescription(AnyLaunchDescriptionSource(str(path)), launch_arguments=case["args"].items()),
    ]))
    service.run()
    for logger in loggers:
        logger.removeHandler(handler)
    errors = [m for m in logs if m.startswith("Caught exception in launch")]
    user = [m for m in logs if m in {"Turtlesim started, spawning turtle", "Spawn finished",
                                     "square done, shutting down", "launch is shutting down"}
            or m.startswith(("mode is ", "robot is ", "timer fired"))]
    return {"processes": started, "error": errors[0] if errors else None, "logs": user}


def show_args(path: Path) -> str:
    """What `ros2 launch --show-args` prints for the file."""
    import contextlib
    import io

    from ros2launch.api import print_arguments_of_launch_file

    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        try:
            print_arguments_of_launch_file(launch_file_path=str(path))
        except Exception as exc:  # the file fails to load: what ros2 launch reports instead
            return f"error: {type(exc).__name__}"
    return out.getvalue()


def main() -> None:
    # launch_ros imports composition_interfaces for composable nodes, which no case uses; the PyPI wheels lack it.
    if "composition_interfaces" not in sys.modules:
        module = types.ModuleType("composition_interfaces")
        service = type("Service", (), {"Request": object, "Response": object})
        module.srv = types.SimpleNamespace(LoadNode=service, UnloadNode=service, ListNodes=service)
        sys.modules["composition_interfaces"] = module
        sys.modules["composition_interfaces.srv"] = module.srv
    import launch.frontend
    import launch_xml
    import launch_yaml
    import launch_ros  # noqa: F401  (exposes node, push-ros-namespace... to the XML and YAML parsers)

    # From source trees the parsers' entry points are not registered: name them as their setup.py does.
    launch.frontend.Parser.frontend_parsers = {"xml": launch_xml.Parser, "yaml": launch_yaml.Parser}
    out = {}
    with tempfile.TemporaryDirectory(prefix="rosgrade-real-launch-") as tmp:
        prefix = Path(tmp) / "install"
        install(prefix, Path(sys.argv[1]))
        os.environ["AMENT_PREFIX_PATH"] = str(prefix)
        os.environ["PATH"] = f"{prefix / 'bin'}:{os.environ.get('PATH', '/usr/bin:/bin')}"
        os.environ.pop("ROSGRADE_MODEL", None)
        for case in json.loads((CASES / "runs.json").read_text()):
            result = record(case, prefix)
            text = json.dumps(result).replace(str(prefix), "<prefix>")
            out[case["id"]] = json.loads(text)
        for file in sorted({case["file"] for case in json.loads((CASES / "runs.json").read_text())}):
            out.setdefault("show_args", {})[file] = show_args(prefix / "share" / "course_pkg" / "launch" / file)
    (CASES / "real_records.json").write_text(json.dumps(out, indent=1, sort_keys=True) + "\n")


if __name__ == "__main__":
    main()
