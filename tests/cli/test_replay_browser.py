"""The replay in a real headless Chromium: it plays, scrubs, follows the keyboard and criterion links, and fits a
phone, on made-up runs whose poses are known (tests/e2e/test_replay_pages.py opens the real reports)."""
from __future__ import annotations

import re
import time
from pathlib import Path

import numpy as np
import pytest

from tests.browser import Browser, chromium

from . import replay_runs as runs

pytestmark = pytest.mark.skipif(chromium() is None, reason="no chromium installed (Debian: apt-get install chromium)")
ROBOT = "replay-move_arc-nominal"
POSE = re.compile(r"at x (?P<x>-?[\d.]+) m, y (?P<y>-?[\d.]+) m, heading (?P<heading>-?\d+)°")


@pytest.fixture(scope="module")
def browser(tmp_path_factory):
    page = tmp_path_factory.mktemp("replay") / "report.html"
    page.write_text(runs.page(), encoding="utf-8")
    with Browser() as browser:
        browser.open(page)
        yield browser


def state(browser: Browser, anchor: str = ROBOT) -> dict:
    return browser.js(f"""(() => {{ const r = window.rosgradeReplays[{anchor!r}];
        return {{t: r.t, playing: r.playing, pose: r.pose.textContent, command: r.command.textContent,
                 shown: Array.from(r.log.children).filter(li => !li.hidden).map(li => li.textContent)}}; }})()""")


def shown_pose(text: str) -> tuple[float, float, float]:
    found = POSE.search(text)
    assert found, text
    return float(found["x"]), float(found["y"]), float(found["heading"])


def test_the_page_runs_without_console_errors(browser):
    assert browser.errors() == []
    assert sorted(browser.js("Object.keys(window.rosgradeReplays)")) == [ROBOT, "replay-turtle_line-nominal"]


def test_play_moves_the_robot_to_the_pose_recorded_at_that_time(browser):
    browser.click(f"#{ROBOT} button.rp-speed[data-speed='4']")
    browser.click(f"#{ROBOT} button.rp-play")
    time.sleep(1.0)
    browser.click(f"#{ROBOT} button.rp-play")
    now = state(browser)
    assert not now["playing"] and 2.0 < now["t"] < 8.0  # 4× for about a second
    x, y, heading = shown_pose(now["pose"])
    expected = runs.arc_pose(now["t"])
    assert abs(x - expected[0]) <= 0.01 and abs(y - expected[1]) <= 0.01
    assert abs(heading - np.degrees(expected[2])) <= 1
    assert "linear.x 0.20 m/s, angular.z 0.10 rad/s" in now["command"]


def test_scrubbing_shows_the_lines_printed_until_then(browser):
    browser.js(f"""(() => {{ const range = document.querySelector('#{ROBOT} input.rp-time');
        range.value = 7.7; range.dispatchEvent(new Event('input')); }})()""")
    now = state(browser)
    assert now["t"] == pytest.approx(7.7)
    assert [line.split(" s ")[1] for line in now["shown"]] == [f"[INFO] step {i}: all is well" for i in range(8)]
    assert shown_pose(now["pose"])[:2] == pytest.approx(runs.arc_pose(7.7)[:2], abs=0.01)


def test_the_keyboard_plays_pauses_and_steps(browser):
    browser.js(f"window.rosgradeReplays[{ROBOT!r}].seek(3)")
    browser.js(f"document.getElementById({ROBOT + '-time'!r}).focus()")
    browser.key("ArrowRight", "ArrowRight", 39)  # on the timeline: one second, not its 0.01 s step
    assert state(browser)["t"] == pytest.approx(4.0)
    browser.js(f"document.querySelector('#{ROBOT} canvas').focus()")
    browser.key(" ", "Space", 32)
    assert state(browser)["playing"]
    browser.key(" ", "Space", 32)
    assert not state(browser)["playing"]


def test_a_criterion_link_jumps_to_the_moment_that_decided_it(browser):
    browser.js("window.scrollTo(0, 0)")
    browser.click("a.rp-jump[href='#replay-move_arc-nominal'][data-t='15.80']")
    now = state(browser)
    assert now["t"] == pytest.approx(15.8) and not now["playing"]
    top = browser.js(f"document.getElementById({ROBOT!r}).getBoundingClientRect().top")
    assert abs(top) < 2  # scrolled to the replay
    assert browser.js("document.activeElement.className") == "rp-play"


def test_the_turtles_pen_line_is_drawn_in_its_colour_up_to_the_turtle(browser):
    anchor = "replay-turtle_line-nominal"
    browser.js(f"window.rosgradeReplays[{anchor!r}].seek(2.5)")
    x, y, _ = shown_pose(state(browser, anchor)["pose"])
    assert (x, y) == pytest.approx((5.5, 5.5), abs=0.02)
    # the canvas pixel halfway along the red stretch (drawn from 1 s on, at x = 4 m), and beyond the turtle
    probe = """(() => {{ const r = window.rosgradeReplays[{a!r}], c = r.canvas, b = r.data.world.bounds;
        const k = c.width / (b[2] - b[0]); const at = (x, y) => Array.from(c.getContext('2d')
        .getImageData(Math.round(x * k), Math.round((b[3] - y) * k), 1, 1).data.slice(0, 3));
        return [at(4.8, 5.5), at(6.5, 5.5)]; }})()""".format(a=anchor)
    red, ahead = browser.js(probe)
    assert red == [255, 0, 0] and ahead == [69, 86, 255]
    browser.js(f"window.rosgradeReplays[{anchor!r}].seek(3.5)")  # after /clear: only what came since
    red, _ = browser.js(probe)
    assert red == [69, 86, 255]


def test_the_page_fits_a_phone(tmp_path):
    page = tmp_path / "report.html"
    page.write_text(runs.page(), encoding="utf-8")
    with Browser(width=390, height=800) as phone:
        phone.open(page)
        assert phone.errors() == []
        assert phone.js("document.documentElement.scrollWidth") <= 390
        assert phone.js(f"document.querySelector('#{ROBOT} canvas').getBoundingClientRect().width") <= 390


def test_walls_and_pillars_are_drawn_where_the_scenario_puts_them(browser):
    probe = f"""(() => {{ const r = window.rosgradeReplays[{ROBOT!r}], c = r.canvas, b = r.data.world.bounds;
        const k = c.width / (b[2] - b[0]); const at = (x, y) => Array.from(c.getContext('2d')
        .getImageData(Math.round((x - b[0]) * k), Math.round((b[3] - y) * k), 1, 1).data.slice(0, 3));
        return [at(-0.5, -0.8), at(2.5, 1.0), at(-0.5, -0.3)]; }})()"""
    pillar, wall, floor = browser.js(probe)
    assert pillar == wall == [107, 107, 107] and floor != pillar
