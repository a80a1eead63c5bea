"""The service_client metric: a client's requests against the fields its parameters set, and its log against the
response it got; and the rubric's grader_nodes, the grader's own server beside the student's client."""
from __future__ import annotations

from dataclasses import replace

import pytest
from scoring_synth import run

from grader.metrics import OutputLine, service_client
from grader.metrics.run import ServiceCall
from grader.rubric import RubricError, load_rubric, load_rubrics

RESPONSE = {"num_guesses": 7, "hint": "The answer is 37!", "correct": False}
PARAMS = service_client.Params(service="/guess_the_number", request={"guess": 99, "cheat": True},
                               reported=["num_guesses", "hint"])


def _measure(request: dict, lines: list[tuple[float, str]], response: dict | None = RESPONSE) -> dict:
    calls = (ServiceCall(2.5, "/guess_the_number", request, response),) if request else ()
    data = replace(run([(4.0, 0.0, 0.0)], t0=2.0), service_calls=calls,
                   lines=tuple(OutputLine(t, "rosout", text, "INFO") for t, text in lines))
    return service_client.METRIC.measure(data, PARAMS)


def test_a_client_that_sends_its_parameters_and_logs_the_response_earns_both() -> None:
    m = _measure({"guess": 99, "cheat": True}, [(2.4, "Sending guess 99"),
                                                (2.6, "attempts: 7\n - A hint: 'The answer is 37!'.")])
    assert m["request_fraction"] == 1.0 and m["reported_fraction"] == 1.0
    assert m["response"] == "num_guesses=7, hint='The answer is 37!'"


def test_an_ignored_parameter_names_the_field_and_value() -> None:
    m = _measure({"guess": 99, "cheat": False}, [(2.6, "7 The answer is 37!")])
    assert m["request_fraction"] == 0.0 and m["first_wrong_request"] == "call 1: cheat = False, expected True"


@pytest.mark.parametrize("text", ["attempts: 17, The answer is 37!", "attempts 0.7 The answer is 37!",
                                  "attempts 7.5 The answer is 37!"])
def test_a_number_counts_only_as_a_whole_number(text: str) -> None:
    m = _measure({"guess": 99, "cheat": True}, [(2.6, text)])
    assert m["reported_fraction"] == 0.5
    assert m["first_unreported"] == "num_guesses = 7 is in no line your node wrote after the call"


def test_lines_before_the_call_do_not_report_its_response() -> None:
    m = _measure({"guess": 99, "cheat": True}, [(2.4, "7 The answer is 37!")])
    assert m["reported_fraction"] == 0.0


def test_no_call_is_said_so() -> None:
    m = _measure({}, [])
    assert m["n_calls"] == 0 and m["request_fraction"] == 0.0
    assert m["first_wrong_request"] == m["no_response"] == "no call to /guess_the_number reached the server"


def test_grader_nodes_are_the_graders_own_and_beside_the_students() -> None:
    rubric = load_rubrics()["number_game_client"]
    assert [(n.script, n.args) for n in rubric.grader_nodes] == [
        ("number_game_server.py", ["*/srv/MyNumberGame", "37", "6"])]


def test_a_grader_node_the_grader_does_not_ship_is_refused(tmp_path) -> None:
    text = load_rubrics()["number_game_client"].source.read_text()
    path = tmp_path / "number_game_client.toml"
    path.write_text(text.replace('script = "number_game_server.py"', 'script = "my_server.py"'))
    with pytest.raises(RubricError, match="the grader ships no node my_server.py; it ships ") as refused:
        load_rubric(path)
    assert "number_game_server.py" in str(refused.value)  # among the nodes it does ship
