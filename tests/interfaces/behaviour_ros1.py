"""The behaviour of game_msgs' genpy classes, as plain JSON: run under Debian's genpy (real_genpy.py) and under
rosgrade's, and compared."""
from __future__ import annotations


def _bytes(msg, io) -> str:
    buffer = io.BytesIO()
    msg.serialize(buffer)
    return buffer.getvalue().hex()


def behaviour(modules: dict, io) -> dict:
    """str, slots, md5sums, constants and bytes of the example package's classes, and a round trip."""
    Guess, Tag = modules["msg"].Guess, modules["msg"].Tag
    Game = modules["srv"].MyNumberGame
    request, response = modules["srv"].MyNumberGameRequest, modules["srv"].MyNumberGameResponse
    guess = Guess(value=7, history=b"\x01\x02", weights=[1.0, 2.0, 3.0], tags=[Tag(name="a")])
    guess.where.x = 1.5
    back = Guess().deserialize(bytes.fromhex(_bytes(guess, io)))
    return {
        "str": {name: str(obj) for name, obj in (("Guess", guess), ("Request", request(guess=3)),
                                                    ("Response", response(hint="Higher")))},
        "slots": {cls.__name__: [list(cls.__slots__), list(cls._slot_types)]
                  for cls in (Guess, Tag, request, response)},
        "types": [Guess._type, Game._type, request._type, response._type, Game._request_class.__name__],
        "md5sums": [Guess._md5sum, Tag._md5sum, Game._md5sum, request._md5sum, response._md5sum],
        "has_header": Guess._has_header,
        "constants": [Guess.LOWEST, Guess.S],
        "bytes": _bytes(guess, io),
        "round_trip": [back.value, back.where.x, list(back.weights), back.tags[0].name],
    }
