"""The messages of number_game_interfaces that real_cdr.py serializes with real rclpy and the tests with rosgrade's
rosidl runtime: built from a module namespace, so that both sides make the very same values."""
from __future__ import annotations


def messages(msg, srv, action, numpy) -> dict:
    """name -> message, from the package's ``msg``/``srv``/``action`` modules."""
    guess = msg.Guess(value=42, history=[1, 2, 3], name="seven", weights=numpy.array([1.0, 2.0, 3.0]))
    guess.where.x = 1.5
    guess.stamp.sec = 3
    feedback = action.ExploreForward.Impl.FeedbackMessage()
    feedback.goal_id.uuid = numpy.arange(16, dtype=numpy.uint8)
    feedback.feedback.current_distance_travelled = 2.5
    return {
        "Guess": guess,
        "Request": srv.MyNumberGame.Request(guess=-5, cheat=True),
        "Response": srv.MyNumberGame.Response(num_guesses=2, hint="Higher", correct=False),
        "FeedbackMessage": feedback,
        "GetResult_Response": action.ExploreForward.Impl.GetResultService.Response(status=4),
    }
