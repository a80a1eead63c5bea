"""Hostile interface files (.msg/.srv/.action) are findings in bounded time, never a crash or a hang of the grader."""
from __future__ import annotations

import os
import threading
import time
from pathlib import Path

from grader.interfaces import InterfaceSet, catalog_for
from grader.interfaces.reading import MAX_ELEMENTS, MAX_FIELDS, MAX_NESTING, MAX_TYPES
from tests.interfaces.workspaces import interfaces, package


def _read_within(root: Path, seconds: float = 10.0, flavour: str = "ros2") -> InterfaceSet:
    """The workspace's interfaces, read in a thread so that a hang fails the test instead of blocking the suite."""
    result: list = []
    worker = threading.Thread(target=lambda: result.append(interfaces(root, flavour)), daemon=True)
    started = time.monotonic()
    worker.start()
    worker.join(seconds)
    assert not worker.is_alive(), f"reading the interfaces took more than {seconds} s"
    assert time.monotonic() - started < seconds
    return result[0]


def _one(found: InterfaceSet, words: str) -> str:
    matching = [f for f in found.findings if words in f]
    assert matching, found.findings
    return matching[0]


def test_a_message_that_contains_itself(tmp_path: Path) -> None:
    package(tmp_path, "loop_interfaces", {"msg/Node.msg": "int32 value\nNode next\n"})
    found = _read_within(tmp_path)
    assert "loop_interfaces/Node -> loop_interfaces/Node contains itself" in _one(found, "contains itself")
    assert not found.types and found.payload is None


def test_a_message_that_contains_itself_through_another_package(tmp_path: Path) -> None:
    package(tmp_path, "a_interfaces", {"msg/A.msg": "b_interfaces/B b\n", "msg/Fine.msg": "int32 x\n"})
    package(tmp_path, "b_interfaces", {"msg/B.msg": "a_interfaces/A a\n", "srv/UsesB.srv": "B b\n---\nbool ok\n"})
    found = _read_within(tmp_path)
    assert "a_interfaces/A -> b_interfaces/B -> a_interfaces/A" in _one(found, "contains itself")
    # what does not depend on the loop stays; the service using B goes with B
    assert sorted(found.types) == ["a_interfaces/msg/Fine"]
    assert found.services == {}


def test_a_million_fields(tmp_path: Path) -> None:
    text = "".join(f"int32 f{i}\n" for i in range(1_000_000))
    package(tmp_path, "huge_interfaces", {"msg/Huge.msg": text, "msg/Small.msg": "int32 x\n"})
    found = _read_within(tmp_path, seconds=5.0)
    assert "KiB" in _one(found, "huge_interfaces/msg/Huge.msg is larger than")
    assert list(found.types) == ["huge_interfaces/msg/Small"]


def test_more_fields_than_a_type_may_have(tmp_path: Path) -> None:
    text = "".join(f"int8 f{i}\n" for i in range(MAX_FIELDS + 1))
    package(tmp_path, "wide_interfaces", {"msg/Wide.msg": text})
    found = _read_within(tmp_path, seconds=5.0)
    assert f"declares {MAX_FIELDS + 1} fields" in _one(found, "wide_interfaces/msg/Wide.msg")


def test_a_package_that_shadows_a_built_in_one(tmp_path: Path) -> None:
    package(tmp_path, "geometry_msgs", {"msg/Twist.msg": "string linear\n"})
    found = _read_within(tmp_path)
    assert "a package ROS already has" in _one(found, "package geometry_msgs")
    assert not found.types
    catalog = catalog_for("ros2", found)
    assert "geometry_msgs/Vector3 linear" in catalog.definition("geometry_msgs/msg/Twist")


def test_a_file_that_defines_a_built_in_type_inside_it(tmp_path: Path) -> None:
    sneaky = "int32 x\n" + "=" * 80 + "\nMSG: geometry_msgs/Twist\nstring linear\n"
    package(tmp_path, "sneaky_interfaces", {"msg/Sneaky.msg": sneaky})
    found = _read_within(tmp_path)
    _one(found, "holds other message definitions")
    assert not found.types


def test_a_package_named_like_a_module_the_node_imports(tmp_path: Path) -> None:
    package(tmp_path, "numpy", {"msg/Array.msg": "int32 x\n"})
    package(tmp_path, "os", {"msg/Path.msg": "string p\n"})
    found = _read_within(tmp_path)
    assert "the node's own libraries use" in _one(found, "package numpy")
    _one(found, "package os")
    assert not found.types


def test_fixed_arrays_that_multiply_through_nesting(tmp_path: Path) -> None:
    package(tmp_path, "big_interfaces", {"msg/C.msg": "float64[1000] v\n", "msg/B.msg": "C[1000] c\n",
                                         "msg/A.msg": "B[1000] b\n", "msg/Flat.msg": "uint8[2000000000] d\n"})
    found = _read_within(tmp_path)
    assert f"rosgrade takes at most {MAX_ELEMENTS}" in _one(found, "big_interfaces/A holds 1000000000 ")
    _one(found, "big_interfaces/Flat holds 2000000000 ")
    assert sorted(found.types) == ["big_interfaces/msg/B", "big_interfaces/msg/C"]  # B: exactly the most


def test_a_fifo_named_like_an_interface_file(tmp_path: Path) -> None:
    folder = package(tmp_path, "fifo_interfaces", {"msg/Fine.msg": "int32 x\n"})
    os.remove(folder / "msg" / "Fine.msg")
    os.mkfifo(folder / "msg" / "Fine.msg")
    found = _read_within(tmp_path, seconds=5.0)  # the workspace lists regular files only: nothing opens the FIFO
    assert not found.types


def test_unknown_types_and_garbage(tmp_path: Path) -> None:
    package(tmp_path, "bad_interfaces", {"msg/Unknown.msg": "nowhere_msgs/Thing t\n",
                                         "srv/Dashes.srv": "int32 a\n---\nint32 b\n---\nint32 c\n",
                                         "msg/Upper.msg": "int32 BadName\n", "msg/Binary.msg": "\x00\x01\x02 \xff\n"})
    found = _read_within(tmp_path)
    _one(found, "unknown type nowhere_msgs/Thing")
    _one(found, "has 2 '---' lines where a .srv file has 1")
    _one(found, "'BadName' is not a valid field name")
    assert not found.types


def test_a_ros1_message_that_contains_itself(tmp_path: Path) -> None:
    package(tmp_path, "loop_msgs", {"msg/Node.msg": "Node[] children\n"}, flavour="ros1")
    found = _read_within(tmp_path, flavour="ros1")
    _one(found, "contains itself")
    assert not found.types


def test_a_chain_of_types_nested_deeper_than_rosgrade_takes(tmp_path: Path) -> None:
    files = {f"msg/T{i}.msg": f"T{i + 1} next\n" for i in range(MAX_NESTING + 5)}
    files[f"msg/T{MAX_NESTING + 5}.msg"] = "int32 end\n"
    package(tmp_path, "deep_interfaces", files)
    found = _read_within(tmp_path)
    assert f"rosgrade takes at most {MAX_NESTING}" in _one(found, f"nests {MAX_NESTING + 1} of the submission's")
    assert len(found.types) == MAX_NESTING + 1  # T5..T37 nest at most 32 others


def test_a_chain_longer_than_the_stack_and_more_files_than_rosgrade_reads(tmp_path: Path) -> None:
    files = {f"msg/T{i}.msg": f"T{i + 1} next\n" for i in range(MAX_TYPES + 20)}
    package(tmp_path, "chain_interfaces", files)
    found = _read_within(tmp_path, seconds=20.0)
    _one(found, f"more than {MAX_TYPES} interface files")
    assert not found.types  # the chain's end was never read: every link uses an unknown type in the end
