"""The behaviour of number_game_interfaces' generated classes, as plain JSON: run under real rosidl_generator_py
classes (real_rosidl.py) and under rosgrade's, and compared."""
from __future__ import annotations


def _error(make) -> str:
    try:
        make()
    except (AssertionError, TypeError, ValueError) as exc:
        return f"{type(exc).__name__}: {exc}"
    return "accepted"


def behaviour(modules: dict) -> dict:
    """Reprs, field types, constants, defaults, equality and field-check messages of the example package."""
    Guess = modules["msg"].Guess
    Game = modules["srv"].MyNumberGame
    Explore = modules["action"].ExploreForward
    instances = {
        "Guess": Guess(), "Request": Game.Request(), "Response": Game.Response(), "Goal": Explore.Goal(),
        "Result": Explore.Result(), "Feedback": Explore.Feedback(),
        "SendGoal_Request": Explore.Impl.SendGoalService.Request(),
        "SendGoal_Response": Explore.Impl.SendGoalService.Response(),
        "GetResult_Response": Explore.Impl.GetResultService.Response(),
        "FeedbackMessage": Explore.Impl.FeedbackMessage(),
    }
    checked = {
        "value_str": lambda: Guess(value="x", check_fields=True),
        "value_big": lambda: Guess(value=2 ** 31, check_fields=True),
        "name_long": lambda: Guess(name="x" * 17, check_fields=True),
        "weights_short": lambda: Guess(weights=[1.0], check_fields=True),
        "where_wrong": lambda: Guess(where=Game.Request(), check_fields=True),
        "guess_float": lambda: Game.Request(guess=1.5, check_fields=True),
        "cheat_int": lambda: Game.Request(cheat=1, check_fields=True),
        "unknown_kw": lambda: Game.Request(gess=1, check_fields=True),
        "fwd_str": lambda: Explore.Goal(fwd_velocity="fast", check_fields=True),
    }
    return {
        "repr": {name: repr(obj) for name, obj in instances.items()},
        "fields": {name: type(obj).get_fields_and_field_types() for name, obj in instances.items()},
        "modules": {name: type(obj).__module__ for name, obj in instances.items()},
        "constants": [Guess.LOWEST, Guess.HIGHEST, Guess.SOURCE],
        "defaults": [Guess.VALUE__DEFAULT, Guess.NAME__DEFAULT, list(Guess.WEIGHTS__DEFAULT)],
        "equal": [Game.Request(guess=3) == Game.Request(guess=3), Game.Request(guess=3) == Game.Request(guess=4),
                  Guess() == Guess(), Guess(weights=[1.0, 0.0, 0.0]) == Guess()],
        "checks": {name: _error(make) for name, make in checked.items()},
        "service_members": sorted(n for n in ("Request", "Response", "Event") if hasattr(Game, n)),
        "action_members": sorted(n for n in ("Goal", "Result", "Feedback", "Impl") if hasattr(Explore, n)),
        "names": [Game.__name__, Explore.__name__, Game.Request.__name__, Explore.Goal.__name__],
    }
