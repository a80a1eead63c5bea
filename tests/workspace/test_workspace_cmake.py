"""CMakeLists.txt read as data: each form of command and argument CMake accepts, and what CMake would refuse."""
from __future__ import annotations

import time

import pytest

from grader.workspace import cmake


def _args(text: str, values: dict[str, str] | None = None) -> list[list[str]]:
    variables = cmake.Variables(values or {})
    return [variables.arguments(command) for command in cmake.parse(text)]


def test_command_names_are_case_insensitive_and_keep_their_line() -> None:
    [first, second] = cmake.parse("project(a)\n\nINSTALL(PROGRAMS x DESTINATION lib/a)\n")
    assert (first.name, first.line) == ("project", 1)
    assert (second.name, second.line) == ("install", 3)


def test_arguments_span_lines_and_comments() -> None:
    text = "install(PROGRAMS  # the nodes\n  scripts/a.py\n\tscripts/b.py\n  DESTINATION lib/p\n)\n"
    assert _args(text) == [["PROGRAMS", "scripts/a.py", "scripts/b.py", "DESTINATION", "lib/p"]]


def test_quoted_arguments_keep_spaces_and_semicolons() -> None:
    assert _args('set(X "a b;c" d;e)') == [["X", "a b;c", "d", "e"]]


def test_quoted_argument_escapes_and_line_continuation() -> None:
    assert _args('message("say \\"hi\\"\\\nthere")') == [['say "hi"there']]


def test_bracket_argument_and_bracket_comment() -> None:
    text = "#[[ a comment\nspanning lines ]]\nset(X [=[raw ${PROJECT_NAME} ]] text]=])\n"
    [command] = cmake.parse(text)
    assert command.line == 3
    assert _args(text, {"PROJECT_NAME": "p"}) == [["X", "raw p ]] text"]]


def test_nested_parentheses_inside_arguments() -> None:
    assert _args("if((A AND B) OR C)\nendif()") == [["A", "AND", "B", "OR", "C"], []]


def test_project_name_and_set_variables_expand() -> None:
    values = {"PROJECT_NAME": "part2_navigation", "DIR": "scripts"}
    assert _args("install(PROGRAMS ${DIR}/a.py DESTINATION lib/${PROJECT_NAME})", values) == [
        ["PROGRAMS", "scripts/a.py", "DESTINATION", "lib/part2_navigation"]]


def test_nested_variable_reference_and_undefined_variable() -> None:
    assert _args("x(${${WHICH}} [${NOPE}])", {"WHICH": "A", "A": "found"}) == [["found", "[]"]]


def test_a_list_variable_splits_into_arguments() -> None:
    assert _args("install(PROGRAMS ${NODES} DESTINATION d)", {"NODES": "a.py;b.py"}) == [
        ["PROGRAMS", "a.py", "b.py", "DESTINATION", "d"]]


@pytest.mark.parametrize("text,line,words", [
    ("project(p)\ninstall(PROGRAMS a.py\n", 2, 'missing ending ")"'),
    ('project(p)\nset(X "open\n)\n', 2, 'missing ending ")"'),
    ("project(p)\nset(X [[never closed)\n", 2, 'missing its closing "]]"'),
    ("#[[ comment never closed\nproject(p)\n", 1, 'missing its closing "]]"'),
    ("project(p)\n\ninstall PROGRAMS a.py\n", 3, 'Expected "("'),
    ("project(p)\n) stray\n", 2, "Expected a command name"),
])
def test_malformed_cmake_is_an_error_naming_its_line(text: str, line: int, words: str) -> None:
    with pytest.raises(cmake.CMakeError) as caught:
        cmake.parse(text)
    assert f"CMakeLists.txt:{line}:" in str(caught.value) and words in str(caught.value)


def test_huge_cmakelists_is_refused_before_parsing() -> None:
    started = time.monotonic()
    with pytest.raises(cmake.CMakeError, match="KiB"):
        cmake.parse("# padding\n" * (cmake.MAX_BYTES // 8))
    assert time.monotonic() - started < 1.0


def test_too_many_commands_are_refused() -> None:
    with pytest.raises(cmake.CMakeError, match="more than"):
        cmake.parse("x()\n" * (cmake.MAX_COMMANDS + 1))


def test_a_variable_that_doubles_is_refused_in_bounded_time() -> None:
    text = "set(A x)\n" + "set(A ${A}${A})\n" * 40
    variables = cmake.Variables({})
    started = time.monotonic()
    with pytest.raises(cmake.CMakeError, match="grows past"):
        for command in cmake.parse(text):
            args = variables.arguments(command)
            variables.values[args[0]] = ";".join(args[1:])
    assert time.monotonic() - started < 1.0


def test_a_value_s_own_reference_text_is_not_expanded_again() -> None:
    assert cmake.Variables({"A": "${A}x", "B": "b"}).expand("${A}-${B}", 1) == "${A}x-b"


def test_references_nested_too_deep_are_refused() -> None:
    with pytest.raises(cmake.CMakeError, match="nest"):
        cmake.Variables({}).expand("${" * 12 + "X" + "}" * 12, 1)
