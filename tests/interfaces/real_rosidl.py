"""Run under the ROS 2 venv's Python: builds a package's interfaces with the real rosidl tool chain's Python
generators (rosidl_adapter, rosidl_generator_type_description, rosidl_generator_py; what `colcon build` runs through
CMake) and prints, as JSON, the RIHS01 hashes and the generated classes' behaviour the tests compare with rosgrade's.

    python real_rosidl.py <package folder> <venv prefix> <work folder> [--hashes-only]

``--hashes-only`` prints the hashes alone (for a package the number-game behaviour probe does not fit: turtlesim).
"""
from __future__ import annotations

import contextlib
import importlib
import json
import sys
from pathlib import Path

from rosidl_adapter import convert_to_idl
from rosidl_generator_py import generate_py
from rosidl_generator_type_description import generate_type_hash

from behaviour import behaviour  # noqa: E402 - the shared probe, beside this file


def main() -> None:
    package_dir, prefix, work = (Path(a).resolve() for a in sys.argv[1:4])
    name = package_dir.name
    idl_dir = work / "idl"
    files = sorted(p.relative_to(package_dir) for kind in ("msg", "srv", "action")
                   for p in (package_dir / kind).glob(f"*.{kind}"))
    with contextlib.redirect_stdout(sys.stderr):  # the adapter reports each file it converts
        idls = [convert_to_idl(package_dir, name, f, idl_dir) for f in files]
    idl_tuples = [f"{idl_dir}:{p.relative_to(idl_dir)}" for p in idls]
    share = prefix / "share"
    includes = [f"{d.name}:{d}" for d in share.iterdir() if d.is_dir()]
    hashes_dir = work / "type_description"
    args = {"package_name": name, "output_dir": str(hashes_dir), "idl_tuples": idl_tuples, "include_paths": includes}
    (work / "hash_args.json").write_text(json.dumps(args))
    generate_type_hash(str(work / "hash_args.json"))
    hashes = {}
    for path in sorted(hashes_dir.rglob("*.json")):
        for item in json.loads(path.read_text())["type_hashes"]:
            hashes[item["type_name"]] = item["hash_string"]
    if "--hashes-only" in sys.argv[4:]:
        print(json.dumps({"hashes": hashes}, indent=1, sort_keys=True))
        return
    py_dir = work / "py"
    args = {"package_name": name, "output_dir": str(py_dir / name), "template_dir":
            str(prefix / "share" / "rosidl_generator_py" / "resource"), "idl_tuples": idl_tuples,
            "target_dependencies": [], "type_description_tuples": [
                f"{p.relative_to(idl_dir)}:{hashes_dir / p.relative_to(idl_dir).with_suffix('.json')}" for p in idls]}
    (work / "py_args.json").write_text(json.dumps(args))
    generate_py(str(work / "py_args.json"), [])
    sys.path.insert(0, str(py_dir))
    module = {kind: importlib.import_module(f"{name}.{kind}") for kind in ("msg", "srv", "action")
              if (package_dir / kind).is_dir()}
    print(json.dumps({"hashes": hashes, "behaviour": behaviour(module)}, indent=1, sort_keys=True))


if __name__ == "__main__":
    main()
