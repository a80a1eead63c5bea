"""The number_game metric on games played on paper: a correct server earns every check, whatever its secrets; each
mistake students make fails its own check alone, naming the call, the field and the value."""
from __future__ import annotations

from dataclasses import replace

import pytest
from number_game_synth import play, scenario_requests
from scoring_synth import run

from grader.metrics import number_game
from grader.metrics.run import ServiceCall
from grader.rubric import load_rubrics

SCENARIO = load_rubrics()["number_game"].scenarios[0]
REQUESTS = scenario_requests(SCENARIO)
CHECKS = ("hints_fraction", "counts_fraction", "cheats_fraction", "correct_fraction")


def _measure(calls: list[ServiceCall]) -> dict:
    data = replace(run([(4.0, 0.0, 0.0)], t0=2.0), service_calls=tuple(calls))
    return number_game.METRIC.measure(data, number_game.Params(calls=len(REQUESTS)))


def _failing(m: dict) -> set[str]:
    return {name for name in CHECKS if m[name] != 1.0}


@pytest.mark.parametrize("secrets", [[42, 7], [0, 99, 50], [84, 75], [100, 100], [57, 80, 3]])
def test_a_correct_server_passes_every_check_whatever_its_secrets(secrets: list[int]) -> None:
    m = _measure(play(REQUESTS, secrets))
    assert _failing(m) == set() and m["answered_fraction"] == 1.0 and m["n_calls"] == len(REQUESTS) == 103
    assert m["n_hints_judged"] > 90 and m["n_cheats_judged"] == 2 and m["n_wins"] >= 1


def test_reversed_hints_fail_the_hints_alone() -> None:
    m = _measure(play(REQUESTS, [42, 7], reversed_hints=True))
    assert _failing(m) == {"hints_fraction"} and m["hints_fraction"] == 0.0
    assert m["first_wrong_hints"] == ("call 2 (guess=0, cheat=False): hint = 'Lower', expected 'Higher' "
                                      "(the secret was 42)")


def test_an_uncounted_cheat_fails_the_cheat_alone() -> None:
    m = _measure(play(REQUESTS, [42, 7], count_cheats=False))
    assert _failing(m) == {"cheats_fraction"}
    assert m["first_wrong_cheats"] == ("call 1 (guess=0, cheat=True): num_guesses = 0, expected 1: a cheat still "
                                       "counts as a guess")


def test_a_server_that_never_says_correct_is_judged_by_its_cheats_secret() -> None:
    calls = [replace(c, response={**c.response, "correct": False,
                                  "hint": "Higher" if c.response["hint"] == "Winner" else c.response["hint"]})
             for c in play(REQUESTS, [42, 42])]
    m = _measure(calls)
    assert "correct_fraction" in _failing(m)
    assert m["first_wrong_correct"] == ("call 44 (guess=42, cheat=False): correct = False, expected True (the "
                                        "secret was 42, the number your cheat hint gave)")


def test_a_cheat_that_hides_the_secret_and_an_unanswered_call_are_named() -> None:
    calls = play(REQUESTS, [42, 7])
    calls[0] = replace(calls[0], response={**calls[0].response, "hint": "No cheating!"})
    calls[-1] = replace(calls[-1], response=None)
    m = _measure(calls)
    assert m["first_wrong_cheats"] == "call 1 (guess=0, cheat=True): hint = 'No cheating!' does not give the secret " \
                                      "number away"
    assert m["answered_fraction"] == 102 / 103
    assert m["first_unanswered"] == "call 103 (guess=0, cheat=True) got no response"


def test_no_calls_are_named_as_such() -> None:
    m = _measure([])
    assert m["answered_fraction"] == 0.0 and m["first_unanswered"].startswith("only 0 of the grader's 103 calls")
    assert m["first_wrong_hints"] == "no call was answered"
