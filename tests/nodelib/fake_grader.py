"""A small stand-in for the grader's lockstep loop: spawns a probe node and answers its channel (tests only)."""
from __future__ import annotations

import json
import os
import struct
import subprocess
import sys
from dataclasses import dataclass, field
from pathlib import Path

from grader.nodelib import pythonpath
from grader.nodelib.common import rosgrade_channel as ch

NODELIB_PATH = pythonpath("ros1")
PROBES = Path(__file__).resolve().parent / "probes"
TICK = ch.CLOCK_PERIOD_NS


def string_msg(text: str) -> bytes:
    """Serialized std_msgs/String."""
    data = text.encode()
    return struct.pack("<I", len(data)) + data


def float64_msg(value: float) -> bytes:
    """Serialized std_msgs/Float64."""
    return struct.pack("<d", value)


@dataclass
class Frame:
    t_ns: int
    kind: str
    data: object


@dataclass
class Run:
    frames: list[Frame]
    returncode: int
    raw_stdout: bytes
    raw_stderr: bytes

    def of(self, kind: str) -> list[Frame]:
        return [f for f in self.frames if f.kind == kind]

    def output(self, stream: int | None = None) -> str:
        return "".join(f.data[1] for f in self.of("OUTPUT") if stream is None or f.data[0] == stream)

    def lines(self) -> list[str]:
        """The probe's stdout lines (probes report with print)."""
        return self.output(1).splitlines()

    def published(self, topic: str) -> list[tuple[int, bytes]]:
        ids = {f.data["id"] for f in self.of("ADVERTISE") if f.data["topic"] == topic}
        return [(f.t_ns, f.data[1]) for f in self.of("PUBLISH") if f.data[0] in ids]


@dataclass
class FakeGrader:
    """Answers every WAIT with a BATCH at the wake time (or an earlier scripted delivery / shutdown).

    The clock is the last multiple of ``TICK``, and 0 in every BATCH that answers a WAIT sent before INIT. Every
    publisher and subscriber counts one connection from the first BATCH after it registered.
    """

    probe: str
    args: list[str] = field(default_factory=list)
    t0_ns: int = 1_403_000_000
    end_ns: int = 30_000_000_000
    messages: list[tuple[int, str, bytes]] = field(default_factory=list)   # (t_ns, topic, bytes)
    shutdown_ns: int | None = None
    params: dict = field(default_factory=lambda: {"/use_sim_time": True})
    ros_namespace: str = ""
    wall_epoch: float = 1_700_000_000.0
    timeout_s: float = 20.0

    def run(self) -> Run:
        node_r, grader_w = os.pipe()
        grader_r, node_w = os.pipe()
        env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "ROS_NAMESPACE")}
        env["PYTHONPATH"] = NODELIB_PATH
        env["ROSGRADE_CHANNEL"] = f"{node_r},{node_w}"
        env["PYTHONHASHSEED"] = "0"   # set iteration order is part of what must be reproducible
        proc = subprocess.Popen([sys.executable, str(PROBES / self.probe), *self.args], env=env,
                                pass_fds=(node_r, node_w), stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        os.close(node_r)
        os.close(node_w)
        frames: list[Frame] = []
        try:
            self._serve(grader_r, grader_w, frames)
        finally:
            os.close(grader_w)
            os.close(grader_r)
            try:
                out, err = proc.communicate(timeout=self.timeout_s)
            except subprocess.TimeoutExpired:
                proc.kill()
                out, err = proc.communicate()
        return Run(frames, proc.returncode, out, err)

    def _serve(self, rfd: int, wfd: int, frames: list[Frame]) -> None:
        reader = ch.FrameReader(rfd, ch.NODE_KINDS)
        now = self.t0_ns
        inited = False
        shutdown_sent = False
        subscribers: dict[str, list[int]] = {}
        unconnected: list[int] = []
        pending = sorted(self.messages, key=lambda m: m[0])
        while True:
            try:
                kind, payload = reader.read()
            except ch.ChannelError:
                return
            name = ch.KIND_NAMES[kind]
            if kind in ch.JSON_KINDS:
                data: object = ch.decode_json(payload)
            elif kind == ch.OUTPUT:
                stream, text = ch.split_output(payload)
                data = (stream, text.decode())
            else:
                data = ch.split_id_bytes(payload)
            frames.append(Frame(now, name, data))
            if kind == ch.HELLO:
                ch.write_all(wfd, ch.encode_json(ch.START, {"t_ns": now, "params": self.params,
                                                            "ros_namespace": self.ros_namespace,
                                                            "wall_epoch": self.wall_epoch}))
            elif kind == ch.INIT:
                inited = True
            elif kind in (ch.ADVERTISE, ch.SUBSCRIBE):
                unconnected.append(data["id"])
                if kind == ch.SUBSCRIBE:
                    subscribers.setdefault(data["topic"], []).append(data["id"])
            elif kind == ch.UNREGISTER:
                for ids in subscribers.values():
                    if data["id"] in ids:
                        ids.remove(data["id"])
            elif kind == ch.WAIT:
                # messages published before anyone subscribed are gone (no history), as in ROS
                pending = [m for m in pending if m[0] > now or subscribers.get(m[1])]
                candidates = [data["wake_ns"]] if data["wake_ns"] is not None else []
                candidates += [m[0] for m in pending[:1]]
                if self.shutdown_ns is not None and not shutdown_sent:
                    candidates.append(self.shutdown_ns)
                target = max(now, min(candidates, default=self.end_ns))
                if target > self.end_ns:
                    return
                now = target
                advance = {"t_ns": now, "clock_ns": now // TICK * TICK if inited else 0,
                           "connections": {str(ident): 1 for ident in unconnected}}
                unconnected = []
                deliveries = []
                while pending and pending[0][0] <= now:
                    _, topic, body = pending.pop(0)
                    deliveries += [(ident, body) for ident in subscribers.get(topic, [])]
                if self.shutdown_ns is not None and not shutdown_sent and now >= self.shutdown_ns:
                    shutdown_sent = True
                    advance["shutdown"] = "ctrl-c"
                ch.write_all(wfd, ch.encode_batch(advance, deliveries))


def frames_as_json(run: Run) -> list:
    """A run's frames without the HELLO (which carries the PID): what must be identical from run to run."""
    return [json.dumps([f.t_ns, f.kind, f.data if not isinstance(f.data, tuple) else
                        [f.data[0], f.data[1] if isinstance(f.data[1], str) else f.data[1].hex()]])
            for f in run.frames if f.kind != "HELLO"]
