"""The number_game task end to end: the grader plays the student's number game server (COM2009 Part 4, its own
MyNumberGame interface in an ament_cmake package) with calls fixed in advance; the reference earns full marks, its
recording holds the grader's requests and the server's responses (the secret it drew is the same every run), re-scores
identically (`rosgrade score` too) and repeats bit for bit. The grader calls the type of the student's own package,
whatever its name, and says what to write when none generates MyNumberGame; the course's server template, which logs
its service's name from get_service_names_and_types(), runs as it does on ROS 2."""
from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from grader.cli import main
from grader.grading import grade_submission
from grader.metrics.run import service_calls
from grader.recording import Recording
from grader.rubric import load_rubrics
from grader.scoring import score_task

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "reference_solutions_ros2_cmake" / "part4_services"


@pytest.fixture(scope="module")
def reference(graded):
    return graded(PACKAGE, ("number_game",)).tasks[0]


def test_the_reference_server_scores_full_marks(reference):
    assert reference.status == "graded", reference.message
    assert reference.score == reference.max_score, {c.id: c.feedback for c in reference.criteria}
    feedback = {c.id: c.feedback for c in reference.criteria}
    assert feedback["cheat"] == "Both cheats gave the secret away (84, 75), counted, and were not correct."
    assert feedback["hints"] == "All 100 hints pointed to the secret."


def test_the_recording_holds_the_graders_game_and_the_servers_answers(reference):
    recording = Recording.open(reference.recordings[0])
    calls = service_calls(recording)
    assert len(calls) == 103 and all(c.service == "/guess_the_number" for c in calls)
    answered = [(c.request["guess"], c.request["cheat"], c.response["num_guesses"], c.response["hint"],
                 c.response["correct"]) for c in calls]
    assert answered[:3] == [(0, True, 1, "The answer is 84!", False), (0, False, 2, "Higher", False),
                            (1, False, 3, "Higher", False)]
    assert answered[85:88] == [(84, False, 86, "Winner", True), (85, False, 1, "Lower", False),
                               (86, False, 2, "Lower", False)]
    assert answered[-1] == (0, True, 17, "The answer is 75!", False)
    assert calls[0].t - 2.0 == pytest.approx(0.5) and calls[-1].t - 2.0 < 3.0
    callers = {(i.topic.rsplit("/", 1)[1], i.callerid, i.origin, i.type) for i in recording.topics()
               if i.topic.startswith("/rosgrade/service/")}
    assert callers == {("request", "/rosgrade", "grader", "part4_services/srv/MyNumberGame_Request"),
                       ("response", "/number_game_service", "node", "part4_services/srv/MyNumberGame_Response")}


def test_the_recording_rescores_identically_and_repeats_bit_for_bit(reference, tmp_path, capsys):
    recordings = {Path(p).stem: Recording.open(p) for p in reference.recordings}
    again = score_task(load_rubrics()["number_game"], recordings)
    assert [c.model_dump() for c in again.criteria] == [c.model_dump() for c in reference.criteria]
    assert main(["score", *reference.recordings, "--task", "number_game", "--json"]) == 0
    [cli] = json.loads(capsys.readouterr().out)["tasks"]
    assert [(c["id"], c["score"], c["feedback"]) for c in cli["criteria"]] == \
        [(c.id, c.score, c.feedback) for c in reference.criteria]
    second = grade_submission(PACKAGE, tmp_path, ["number_game"]).tasks[0]
    assert Path(second.recordings[0]).read_bytes() == Path(reference.recordings[0]).read_bytes()


def _renamed(tmp_path: Path, name: str) -> Path:
    """The reference package under another name, its scripts importing their srv from it."""
    package = tmp_path / "src" / name
    shutil.copytree(PACKAGE, package)
    for path in [package / "CMakeLists.txt", package / "package.xml", *package.glob("scripts/*.py")]:
        path.write_text(path.read_text().replace("part4_services", name))
    return tmp_path / "src"


def test_a_package_of_another_name_is_called_with_its_own_type(reference, tmp_path):
    task = grade_submission(_renamed(tmp_path, "my_services"), tmp_path / "out", ["number_game"]).tasks[0]
    assert task.score == task.max_score, task.message or {c.id: c.feedback for c in task.criteria}
    requests = {i.type for i in Recording.open(task.recordings[0]).topics() if i.topic.endswith("/request")}
    assert requests == {"my_services/srv/MyNumberGame_Request"}


def test_a_submission_that_generates_no_mynumbergame_is_told_what_to_write(tmp_path):
    src = _renamed(tmp_path, "part4_services")
    cmake = src / "part4_services" / "CMakeLists.txt"
    cmake.write_text(cmake.read_text().replace('  "srv/MyNumberGame.srv"\n', ""))
    task = grade_submission(src, tmp_path / "out", ["number_game"]).tasks[0]
    assert task.status == "error" and task.score == 0
    assert task.message == ("no package in your submission generates the srv type MyNumberGame this task calls: write "
                            "srv/MyNumberGame.srv in your package and list \"srv/MyNumberGame.srv\" in "
                            "rosidl_generate_interfaces() in its CMakeLists.txt")


def test_the_course_templates_service_name_line_is_logged_as_on_ros2(tmp_path):
    src = _renamed(tmp_path, "part4_services")
    script = src / "part4_services" / "scripts" / "my_number_game.py"
    text = script.read_text()
    line = 'self.get_logger().info("The \'/guess_the_number\' service is active.")'
    assert line in text
    script.write_text(text.replace(line, 'self.get_logger().info(\n            '
                                   'f"The \'{self.get_service_names_and_types()[0][0]}\' service is active.")'))
    task = grade_submission(src, tmp_path / "out", ["number_game"]).tasks[0]
    assert task.score == task.max_score, task.message or {c.id: c.feedback for c in task.criteria}
    said = [text for _, stream, text in Recording.open(task.recordings[0]).output_lines() if stream == "rosout"]
    assert said[0] == "The '/guess_the_number' service is active."
