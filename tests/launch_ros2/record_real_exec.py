"""Record what the nodes an ExecuteProcess `ros2 run` starts receive under real ROS 2 Jazzy launch and ros2run (run
where real launch is installed; writes cases/real_exec_records.json).

``python record_real_exec.py ROS2CLI`` under an interpreter that imports real launch and launch_ros (Jazzy);
ROS2CLI is a checkout of ros2cli's jazzy branch, whose ros2cli, ros2pkg and ros2run packages the stand-in `ros2`
command imports to carry out `ros2 run` as the real command does. It installs nothing and fetches nothing: the case
package is laid out as colcon would install it in a temporary prefix, each executable a stand-in that records the
argv it receives and the content of each parameter file it is handed.
"""
from __future__ import annotations

import json
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
FILES = {"exec_ros2_run": ("exec_ros2_run.launch.py", {}), "exec_ros2_run_speed": ("exec_ros2_run.launch.py",
                                                                                    {"speed": "0.7"})}
EXECUTABLES = ("mover", "square", "talker", "listener")
STAND_IN = f"""#!{sys.executable}
import json, os, sys
files = [open(path).read() for flag, path in zip(sys.argv, sys.argv[1:]) if flag == '--params-file']
with open(os.environ['ROSGRADE_ARGV_LOG'], 'a') as log:
    log.write(json.dumps({{'argv': sys.argv, 'params_files': files}}) + '\\n')
"""
ROS2 = f"""#!{sys.executable}
import argparse, sys
from ros2run.command.run import RunCommand
parser = argparse.ArgumentParser(prog='ros2 run')
command = RunCommand()
command.add_arguments(parser, 'ros2')
assert sys.argv[1] == 'run', sys.argv
sys.exit(command.main(parser=parser, args=parser.parse_args(sys.argv[2:])))
"""


def _executable(path: Path, text: str) -> None:
    path.write_text(text)
    path.chmod(stat.S_IRWXU)


def install(prefix: Path) -> None:
    """The case package as colcon would install it, with stand-in executables, and the stand-in `ros2` command."""
    index = prefix / "share" / "ament_index" / "resource_index" / "packages"
    index.mkdir(parents=True)
    (index / "course_pkg").write_text("")
    for folder in ("launch", "config"):
        shutil.copytree(PACKAGE / folder, prefix / "share" / "course_pkg" / folder)
    lib = prefix / "lib" / "course_pkg"
    lib.mkdir(parents=True)
    for name in EXECUTABLES:
        _executable(lib / name, STAND_IN)
    (prefix / "bin").mkdir()
    _executable(prefix / "bin" / "ros2", ROS2)


def record(file: str, args: dict[str, str], prefix: Path, log: Path) -> list[dict]:
    """What each node received, sorted (launch starts processes of one moment concurrently)."""
    import launch
    from launch.actions import IncludeLaunchDescription
    from launch.launch_description_sources import AnyLaunchDescriptionSource

    log.write_text("")
    service = launch.LaunchService()
    path = prefix / "share" / "course_pkg" / "launch" / file
    service.include_launch_description(launch.LaunchDescription([
        IncludeLaunchDescription(AnyLaunchDescriptionSource(str(path)), launch_arguments=args.items())]))
    service.run()
    started = [json.loads(line) for line in log.read_text().splitlines()]
    for entry in started:  # the executable's name, each parameter file by content (paths differ by run)
        entry["argv"] = [os.path.basename(entry["argv"][0]), *("<params-file>" if flag == "--params-file" else word
                                                               for flag, word in zip(entry["argv"], entry["argv"][1:]))]
    return sorted(started, key=json.dumps)


def main() -> None:
    # launch_ros imports composition_interfaces for composable nodes, which no case uses; the PyPI wheels lack it.
    stub = types.ModuleType("composition_interfaces")
    service = type("Service", (), {"Request": object, "Response": object})
    services = types.SimpleNamespace(LoadNode=service, UnloadNode=service, ListNodes=service)
    stub.srv = services  # type: ignore[attr-defined]
    sys.modules.setdefault("composition_interfaces", stub)
    sys.modules.setdefault("composition_interfaces.srv", services)  # type: ignore[arg-type]
    source = Path(sys.argv[1]).resolve()
    out = {}
    with tempfile.TemporaryDirectory(prefix="rosgrade-real-exec-") as tmp:
        prefix = Path(tmp) / "install"
        install(prefix)
        log = Path(tmp) / "argv.jsonl"
        os.environ["AMENT_PREFIX_PATH"] = str(prefix)
        os.environ["ROSGRADE_ARGV_LOG"] = str(log)
        os.environ["PATH"] = f"{prefix / 'bin'}:{os.environ.get('PATH', '/usr/bin:/bin')}"
        paths = [str(source / name) for name in ("ros2cli", "ros2pkg", "ros2run")]
        os.environ["PYTHONPATH"] = os.pathsep.join([*paths, os.environ.get("PYTHONPATH", "")])
        for case_id, (file, args) in FILES.items():
            out[case_id] = {"file": file, "args": args, "started": record(file, args, prefix, log)}
    (CASES / "real_exec_records.json").write_text(json.dumps(out, indent=1, sort_keys=True) + "\n")


if __name__ == "__main__":
    main()
