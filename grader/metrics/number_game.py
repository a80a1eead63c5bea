"""The number game (COM2009 Part 4): a guess-the-number server judged from the grader's own fixed calls, each response
against the secret in force, which the server itself gives away (a cheat's hint, or the guess it called correct)."""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Any

from grader.metrics.base import Measurement, Metric, MetricParams
from grader.metrics.run import RunData, ServiceCall

NUMBER = re.compile(r"-?\d+")
CHECKS = ("hints", "counts", "cheats", "correct")  # what each criterion judges, as quantities name it


class Params(MetricParams):
    """The game's service, and how many calls the scenario makes to it."""

    service: str = "/guess_the_number"
    calls: int = 0


@dataclass(frozen=True)
class _Turn:
    """One answered call, numbered from 1, with the secret of its game (None: the server never gave it away)."""

    number: int
    guess: int
    cheat: bool
    num_guesses: Any
    hint: str
    correct: Any
    secret: int | None
    secret_from: str  # how the server gave the secret away: "win" (the guess it called correct) or "cheat"
    count_expected: tuple[int, ...]  # what num_guesses may be: one more than the call before, or 1 in a new game


def _describe(turn: _Turn) -> str:
    return f"call {turn.number} (guess={turn.guess}, cheat={turn.cheat})"


def _cheat_number(hint: str) -> int | None:
    found = NUMBER.search(hint)
    return None if found is None else int(found.group())


def _games(calls: list[ServiceCall]) -> list[list[tuple[int, ServiceCall]]]:
    """The answered calls cut into games: a response with correct = true ends its game (the course's server then
    draws a new secret)."""
    games: list[list[tuple[int, ServiceCall]]] = [[]]
    for number, call in enumerate(calls, 1):
        if call.response is None:
            continue
        games[-1].append((number, call))
        if call.response.get("correct") is True:
            games.append([])
    return [game for game in games if game]


def _turns(calls: list[ServiceCall]) -> list[_Turn]:
    turns = []
    for game in _games(calls):
        last = game[-1][1]
        secret, source = None, ""
        if last.response.get("correct") is True and not last.request.get("cheat"):
            secret, source = int(last.request.get("guess")), "win"
        else:
            revealed = [_cheat_number(str(c.response.get("hint", ""))) for _, c in game if c.request.get("cheat")]
            revealed = [n for n in revealed if n is not None]
            if revealed:
                secret, source = revealed[0], "cheat"
        for number, call in game:
            before = calls[number - 2].response if number > 1 else None
            if number == 1:
                expected: tuple[int, ...] = (1,)
            elif before is None or not isinstance(before.get("num_guesses"), int):
                expected = ()  # the call before got no response: nothing to count from
            elif before.get("correct") is True:
                expected = (1, before["num_guesses"] + 1)
            else:
                expected = (before["num_guesses"] + 1,)
            turns.append(_Turn(number, int(call.request.get("guess")), bool(call.request.get("cheat")),
                               call.response.get("num_guesses"), str(call.response.get("hint", "")),
                               call.response.get("correct"), secret, source, expected))
    return turns


def _hint_error(turn: _Turn) -> str | None:
    if turn.cheat or turn.secret is None or turn.guess == turn.secret:
        return None
    want, other = ("Higher", "Lower") if turn.guess < turn.secret else ("Lower", "Higher")
    text = turn.hint.lower()
    if want.lower() in text and other.lower() not in text:
        return None
    return f"{_describe(turn)}: hint = {turn.hint!r}, expected {want!r} (the secret was {turn.secret})"


def _count_error(turn: _Turn) -> str | None:
    if not turn.count_expected or turn.num_guesses in turn.count_expected:
        return None
    return (f"{_describe(turn)}: num_guesses = {turn.num_guesses!r}, expected "
            f"{' or '.join(map(str, turn.count_expected))}")


def _cheat_error(turn: _Turn) -> str | None:
    if not turn.cheat:
        return None
    if turn.correct is not False:
        return f"{_describe(turn)}: correct = {turn.correct!r}, expected False: a cheat never wins"
    count = _count_error(turn)
    if count is not None:
        return f"{count}: a cheat still counts as a guess"
    number = _cheat_number(turn.hint)
    if number is None:
        return f"{_describe(turn)}: hint = {turn.hint!r} does not give the secret number away"
    if turn.secret_from == "win" and number != turn.secret:
        return (f"{_describe(turn)}: hint = {turn.hint!r}, but the secret was {turn.secret} (your server called "
                f"guess={turn.secret} correct)")
    return None


def _correct_error(turn: _Turn) -> str | None:
    if turn.cheat or turn.secret is None:
        return None
    want = turn.guess == turn.secret
    if turn.correct is want:
        return None
    said = "your server's correct guess" if turn.secret_from == "win" else "the number your cheat hint gave"
    return f"{_describe(turn)}: correct = {turn.correct!r}, expected {want} (the secret was {turn.secret}, {said})"


def _share(turns: list[_Turn], check) -> tuple[int, int, str]:
    """How many turns the check judged, how many it passed, and the first failure."""
    judged = [turn for turn in turns if _applies(check, turn)]
    errors = [error for error in map(check, judged) if error is not None]
    return len(judged), len(judged) - len(errors), errors[0] if errors else ""


def _applies(check, turn: _Turn) -> bool:
    if check is _hint_error:
        return not turn.cheat and turn.secret is not None and turn.guess != turn.secret
    if check is _count_error:
        return not turn.cheat and bool(turn.count_expected)
    if check is _cheat_error:
        return turn.cheat
    return not turn.cheat and turn.secret is not None


def _fraction(ok: int, judged: int) -> float:
    return ok / judged if judged else math.nan


def measure(run: RunData, params: Params) -> Measurement:
    """Judge every answered call: hints against the secret of its game, counts against the call before, cheats
    (the secret given away, counted, never correct) and correct flags; each criterion names its first wrong call."""
    calls = [c for c in run.service_calls if c.service == params.service]
    n_answered = sum(c.response is not None for c in calls)
    first_unanswered = next((f"call {n} (guess={c.request.get('guess')}, cheat={c.request.get('cheat')}) got no "
                             "response" for n, c in enumerate(calls, 1) if c.response is None), "")
    if not first_unanswered and len(calls) < params.calls:
        first_unanswered = (f"only {len(calls)} of the grader's {params.calls} calls reached a server: is "
                            f"{params.service} offered with your own MyNumberGame type?")
    turns = _turns(calls)
    quantities: dict[str, Any] = {
        "n_calls": len(calls), "n_answered": n_answered,
        "answered_fraction": _fraction(n_answered, params.calls or len(calls)),
        "first_unanswered": first_unanswered,
        "secrets": ", ".join(str(s) for s in dict.fromkeys(t.secret for t in turns if t.secret is not None)),
        "n_wins": sum(t.correct is True and not t.cheat for t in turns),
    }
    for name, check in zip(CHECKS, (_hint_error, _count_error, _cheat_error, _correct_error)):
        judged, ok, first = _share(turns, check)
        quantities.update({f"n_{name}_judged": judged, f"{name}_fraction": _fraction(ok, judged),
                           f"first_wrong_{name}": first or ("" if judged else _nothing_judged(name, turns))})
    return quantities


def _nothing_judged(name: str, turns: list[_Turn]) -> str:
    if not turns:
        return "no call was answered"
    if name == "cheats":
        return "no cheat call was answered"
    return "the secret never showed: no guess was called correct and no cheat's hint held a number"


METRIC = Metric(
    name="number_game",
    params=Params,
    quantities=frozenset({"n_calls", "n_answered", "answered_fraction", "first_unanswered", "secrets", "n_wins"}
                         | {q for name in CHECKS
                            for q in (f"n_{name}_judged", f"{name}_fraction", f"first_wrong_{name}")}),
    measure=measure,
)
