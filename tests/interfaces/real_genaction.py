"""Run under Debian's Python (python3-genmsg, python3-genpy, actionlib_msgs' genaction.py): expands a catkin
package's .action files into the seven .msg files as catkin's add_action_files does, generates their genpy classes
and prints, as JSON, each class's md5sum and slot types, which the tests compare with rosgrade's.

    /usr/bin/python3 real_genaction.py <package folder> <work folder>
"""
from __future__ import annotations

import importlib
import json
import subprocess
import sys
from pathlib import Path

import genmsg
import genmsg.msg_loader as loader
from genpy.generator import MsgGenerator

GENACTION = "/usr/lib/actionlib_msgs/genaction.py"
DEPENDENCIES = ("std_msgs/Header", "actionlib_msgs/GoalID", "actionlib_msgs/GoalStatus", "geometry_msgs/Point")


def _dependency_folders(work: Path) -> dict[str, list[str]]:
    """The .msg files of the dependencies, from the definitions the installed classes carry."""
    search: dict[str, list[str]] = {}
    for name in DEPENDENCIES:
        package, short = name.split("/")
        cls = getattr(importlib.import_module(f"{package}.msg"), short)
        folder = work / "deps" / package / "msg"
        folder.mkdir(parents=True, exist_ok=True)
        (folder / f"{short}.msg").write_text(cls._full_text.split("=" * 80)[0])
        search.setdefault(package, []).append(str(folder))
    return search


def main() -> None:
    package_dir, work = (Path(a).resolve() for a in sys.argv[1:3])
    package = package_dir.name
    msg_dir = work / "msg" / package
    for action in sorted((package_dir / "action").glob("*.action")):
        subprocess.run([sys.executable, GENACTION, str(action), "-o", str(msg_dir)], check=True,
                       capture_output=True)
    search = _dependency_folders(work)
    search[package] = [str(msg_dir)]
    files = sorted(str(p) for p in msg_dir.glob("*.msg"))
    out = work / "py" / package
    MsgGenerator().generate_messages(package, files, str(out / "msg"), search)
    (out / "msg" / "__init__.py").write_text("".join(f"from ._{Path(f).stem} import *\n" for f in files))
    (out / "__init__.py").write_text("")
    context = genmsg.MsgContext.create_default()
    md5s = {}
    for path in files:
        spec = loader.load_msg_from_file(context, path, f"{package}/{Path(path).stem}")
        loader.load_depends(context, spec, search)
        md5s[spec.full_name] = genmsg.compute_md5(context, spec)
    sys.path.insert(0, str(out.parent))
    module = importlib.import_module(f"{package}.msg")
    classes = {f"{package}/{Path(f).stem}": getattr(module, Path(f).stem) for f in files}
    print(json.dumps({name: {"md5sum": md5s[name], "class_md5sum": cls._md5sum, "slots": list(cls.__slots__),
                             "slot_types": list(cls._slot_types), "str": str(cls())}
                      for name, cls in sorted(classes.items())}, indent=1, sort_keys=True))


if __name__ == "__main__":
    main()
