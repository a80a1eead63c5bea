"""One line of what to change for the ROS 2 launch mistakes students make most, after launch's own error text."""
from __future__ import annotations

import re

from grader.workspace.model import Workspace


def hint_for(message: str, workspace: Workspace) -> str:
    """One line of what to change, for the mistakes students make most."""
    if match := re.search(r"package '([^']+)' not found", message):
        names = ", ".join(sorted(workspace.folders)) or "none"
        return (f"No package.xml in the submission says <name>{match[1]}</name> (its packages: {names}); turtlesim "
                "is the grader's, and simulators and tools (rviz2, gazebo, nav2) are listed but never run.")
    if match := re.search(r"executable '([^']+)' not found on the libexec directory '[^']*/lib/([^/']+)'", message):
        package = workspace.package(match[2])
        built = ", ".join(sorted(e.name for e in package.executables)) if package else ""
        return (f"The build of {match[2]} installs: {built or 'no executables'} (console_scripts in setup.py, or "
                "install(PROGRAMS ...)/install(TARGETS ...) in CMakeLists.txt); exec= names one of those.")
    if match := re.search(r"launch configuration '([^']+)' does not exist", message):
        return (f"Declare it before it is used: DeclareLaunchArgument('{match[1]}', default_value=...) in Python, "
                f'<arg name="{match[1]}" default="..."/> in XML.')
    if "[Errno 27] File too large" in message:
        return ("The launch file printed (or wrote) more than rosgrade lets it while it is read; print less, and "
                "only from the nodes it starts.")
    if match := re.search(r"missing required argument '([^']+)'", message):
        return f"Give it a value: {match[1]}:=VALUE after the launch file (or a default_value in the file)."
    return ""
