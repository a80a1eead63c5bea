"""Run under Debian's Python (python3-genpy, python3-genmsg, the std_msgs/geometry_msgs classes): generates genpy
classes for a catkin package's .msg/.srv files as `catkin_make` would (genmsg's md5sums and full texts, genpy's
code) and prints, as JSON, what the tests compare with rosgrade's genpy.

    /usr/bin/python3 real_genpy.py <package folder> <work folder>
"""
from __future__ import annotations

import importlib
import io
import json
import sys
from pathlib import Path

import genmsg
import genmsg.msg_loader as loader
from genpy.generator import MsgGenerator, SrvGenerator

from behaviour_ros1 import behaviour  # noqa: E402 - the shared probe, beside this file

DEPENDENCIES = ("std_msgs/Header", "geometry_msgs/Point")


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
    search = _dependency_folders(work)
    search[package] = [str(package_dir / "msg")]
    out = work / "py" / package
    md5s: dict[str, str] = {}
    texts: dict[str, str] = {}
    context = genmsg.MsgContext.create_default()
    for kind, generator, load in (("msg", MsgGenerator(), loader.load_msg_from_file),
                                  ("srv", SrvGenerator(), loader.load_srv_from_file)):
        files = sorted(str(p) for p in (package_dir / kind).glob(f"*.{kind}"))
        if not files:
            continue
        generator.generate_messages(package, files, str(out / kind), search)
        (out / kind / "__init__.py").write_text("".join(
            f"from ._{Path(f).stem} import *\n" for f in files))
        for path in files:
            name = f"{package}/{Path(path).stem}"
            spec = load(context, path, name)
            loader.load_depends(context, spec, search)
            md5s[name] = genmsg.compute_md5(context, spec)
            if kind == "msg":
                texts[name] = genmsg.compute_full_text(context, spec)
    (out / "__init__.py").write_text("")
    sys.path.insert(0, str(out.parent))
    modules = {kind: importlib.import_module(f"{package}.{kind}") for kind in ("msg", "srv")
               if (package_dir / kind).is_dir()}
    print(json.dumps({"md5sums": md5s, "full_texts": texts, "behaviour": behaviour(modules, io)}, indent=1,
                     sort_keys=True))


if __name__ == "__main__":
    main()
