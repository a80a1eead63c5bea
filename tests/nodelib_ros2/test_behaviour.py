"""rosgrade's ROS 2 message classes and codec on their own: the behaviour nodes rely on (behaviour.py, subprocess)."""
from __future__ import annotations

import pytest

from .helpers import run_json

IMPORT_BUDGET_MS = 100  # ~6 ms with .pyc files and the node bootstrap's stdlib imports loaded; generous for CI noise


@pytest.fixture(scope="module")
def seen() -> dict:
    return run_json(["behaviour.py"])


def test_import_is_cheap(seen):
    assert seen["import_ms"] < IMPORT_BUDGET_MS


def test_repr_is_rosidl_text(seen):
    assert seen["repr"] == "geometry_msgs.msg.Vector3(x=0.0, y=0.0, z=0.0)"


def test_package_module_exposes_classes(seen):
    assert seen["module_attr"] and seen["dir"]
    assert seen["unknown_name"] == "AttributeError: module 'geometry_msgs.msg' has no attribute 'Nope'"


def test_unknown_kwargs_ignored_without_field_checks_as_jazzy(seen):
    assert seen["bad_kwarg_default"] == "geometry_msgs.msg.Vector3(x=0.0, y=0.0, z=0.0)"


def test_unknown_kwargs_rejected_with_field_checks(seen):
    assert seen["bad_kwarg_checked"] == "AssertionError: Invalid arguments passed to constructor: bar, foo"


@pytest.mark.parametrize("probe, message", [
    ("setter_int", "AssertionError: The 'x' field must be of type 'float'"),
    ("setter_str", "AssertionError: The 'x' field must be of type 'float'"),
    ("setter_range", "AssertionError: The 'data' field must be an unsigned integer in [0, 255]"),
    ("setter_f32_range", "AssertionError: The 'data' field must be a float in [-3.402823466e+38, 3.402823466e+38]"),
])
def test_checked_setters_raise_rosidl_messages(seen, probe, message):
    assert seen[probe] == message


def test_fixed_arrays_are_numpy_and_sequences_array(seen):
    assert (seen["cov_type"], seen["cov_dtype"], seen["ranges_type"]) == ("ndarray", "float64", "array")
    assert seen["ranges_list_set"] == "array('f', [1.0, 2.0])"


def test_equality(seen):
    assert seen["eq"] == [True, False, True]
    assert seen["eq_one_cov"] is False


def test_fields_and_field_types_is_a_copy(seen):
    assert seen["fields"] == {"linear": "geometry_msgs/Vector3", "angular": "geometry_msgs/Vector3"}
    assert seen["fields_copy"]


def test_constants(seen):
    assert seen["log_info"] == [20, 40]


def test_empty_message_has_no_fields_but_one_wire_byte(seen):
    assert seen["empty"] == ["std_msgs.msg.Empty()", "0001000000"]


def test_type_name_and_hash(seen):
    assert seen["type_name"] == ["nav_msgs/msg/Odometry", "nav_msgs/msg/Odometry", "std_srvs/srv/SetBool"]
    assert seen["type_hash"] == "RIHS01_9c45bf16fe0983d80e3cfe750d6835843d265a9a6c46bd2e609fcddde6fb8d2a"


def test_service_classes(seen):
    assert seen["srv"] == ["std_srvs.srv.SetBool_Request(data=True)", "SetBool_Response", "Empty_Event",
                           "NotImplementedError: Service classes can not be instantiated"]
    assert seen["type_support"] == [True, True]


def test_int_in_float_field_serializes_as_rosidl_c_reads_it(seen):
    assert seen["int_in_float"] == 5e-324


def test_conversion_failures(seen):
    assert seen["i32_float"].startswith("FieldConversionError: ")
    assert seen["u8_wrap"] == "000100002c"
    assert seen["str_int"] == "TypeError: bad argument type for built-in operation"


@pytest.mark.parametrize("probe", ["decode_header", "decode_short", "decode_huge_count"])
def test_malformed_bytes_raise_decode_error(seen, probe):
    assert seen[probe].startswith("DecodeError: ")


def test_trailing_padding_is_ignored(seen):
    assert seen["decode_padded"] == "geometry_msgs.msg.Vector3(x=2.0, y=0.0, z=0.0)"


def test_decoded_containers(seen):
    assert seen["decoded_types"] == ["array", "f", "str"]
    assert seen["decoded_cov"] == ["ndarray", "float64", True]
