"""`rosgrade launch`: what a launch file sets and starts, as roslaunch (XML) or ros2 launch (Python, XML, YAML) would."""
from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

from grader.cli import EXIT_OK, CliError


def _launch_target(args: argparse.Namespace) -> tuple[Path, dict[str, Path], dict[str, str]]:
    """The launch file, the packages $(find) sees and the args, from `FILE args...` or `PKG FILE args...`."""
    from grader.launch import enclosing_package, find_packages
    from grader.runtime.scripts import candidates

    words = list(args.args)
    # `roslaunch PKG FILE`: a bare package name (no path, no extension) that is not a file here, then a file name.
    by_package = (not args.file.exists() and str(args.file).replace("_", "a").isalnum() and bool(words)
                  and ":=" not in words[0])
    file_name = words.pop(0) if by_package else None
    values: dict[str, str] = {}
    for item in words:
        name, sep, value = item.partition(":=")
        if not sep or not name:
            raise CliError(f"{item!r} is not an arg; pass launch args as name:=value")
        values[name] = value
    if by_package:
        roots = args.packages or [Path.cwd()]
    else:
        package = enclosing_package(args.file.resolve())
        roots = args.packages or ([package.parent] if package else [args.file.resolve().parent])
    packages: dict[str, Path] = {}
    for root in roots:
        packages = find_packages(root) | packages
    if not by_package:
        return args.file, packages, values
    pkg = str(args.file)
    if pkg not in packages:
        raise CliError(f"no package named {pkg} under {', '.join(map(str, roots))} (package.xml <name>); "
                       "pass --packages DIR or the launch file's path")
    found = candidates(packages[pkg], file_name)
    if not found:
        raise CliError(f"no launch file named {file_name} in package {pkg} ({packages[pkg]})")
    return found[0], packages, values


def cmd_launch(args: argparse.Namespace) -> int:
    """Print what a launch file sets and starts, exactly as `roslaunch --dump-params` / `--nodes` print it."""
    from grader.launch import LaunchError, dump_params, node_names, read_launch
    from grader.launch import ros2_cli

    if ros2_cli.is_ros2_target(args.file, args.args, args.workspace):
        mode = "json" if args.json else "show-args" if args.show_args else "dump-params" if args.dump_params \
            else "nodes"
        try:
            text, notes = ros2_cli.command(args.file, args.args, args.workspace, mode)
        except ros2_cli.Ros2LaunchError as exc:
            raise CliError(str(exc)) from None
        for note in notes:
            print(f"rosgrade: note: {note}", file=sys.stderr)
        sys.stdout.write(text)
        return EXIT_OK
    if args.json or args.show_args:
        raise CliError("--json and --show-args are for ROS 2 launch files (.launch.py); for roslaunch XML use "
                       "--nodes or --dump-params")
    if not (args.nodes or args.dump_params):
        raise CliError("say what to print: --nodes or --dump-params")
    file, packages, values = _launch_target(args)
    try:
        launch = read_launch(file, values, packages, os.environ)
    except LaunchError as exc:
        raise CliError(str(exc)) from None
    for note in launch.notes:
        print(f"rosgrade: note: {note}", file=sys.stderr)
    for world in launch.worlds:
        print(f"rosgrade: note: {world.where}: {world.package}/{world.file} is simulated by rosgrade ({world.robot} "
              f"at x={world.x:g}, y={world.y:g}); its Gazebo nodes and parameters are not listed", file=sys.stderr)
    sys.stdout.write(dump_params(launch) if args.dump_params else node_names(launch))
    return EXIT_OK
