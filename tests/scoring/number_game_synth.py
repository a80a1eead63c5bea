"""A number game server played on paper: the responses the course's server gives the grader's calls, with the
mistakes students make switchable, for the number_game metric's tests."""
from __future__ import annotations

from grader.metrics.run import ServiceCall
from grader.rubric import Scenario

SERVICE = "/guess_the_number"


def play(requests: list[tuple[int, bool]], secrets: list[int], *, reversed_hints: bool = False,
         count_cheats: bool = True, t0: float = 2.0) -> list[ServiceCall]:
    """Each request (guess, cheat) answered by a server whose games have the given secrets in turn (a win starts
    the next game, its count from 0)."""
    secrets, count, calls = list(secrets), 0, []
    for k, (guess, cheat) in enumerate(requests):
        secret = secrets[0]
        if cheat:
            count += count_cheats
            response = {"num_guesses": count, "hint": f"The answer is {secret}!", "correct": False}
        else:
            count += 1
            below = guess < secret
            hint = "Winner" if guess == secret else ("Lower" if below == reversed_hints else "Higher")
            response = {"num_guesses": count, "hint": hint, "correct": guess == secret}
            if guess == secret:
                secrets.pop(0)
                count = 0
        calls.append(ServiceCall(t0 + 0.5 + 0.01 * k, SERVICE, {"guess": guess, "cheat": cheat}, response))
    return calls


def scenario_requests(scenario: Scenario) -> list[tuple[int, bool]]:
    """The (guess, cheat) of each of a scenario's calls, in order."""
    return [(c.request["guess"], c.request["cheat"]) for c in scenario.service_calls]
