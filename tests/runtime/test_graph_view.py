"""The run's graph as one node sees it (grader/runtime/graph.py): discovery under ROS 2, at once under ROS 1, closed
endpoints and ended nodes gone, one encoding until something changes, and a flooding run cut to the frame cap."""
from __future__ import annotations

import json

import pytest

from grader.runtime.graph import FixedNode, GraphError, GraphView, Peer
from grader.runtime.node_link import Endpoint, NodeState

DISCOVERY = 500_000_000


def _endpoint(ident: int, topic: str, type_name: str, at: int = 0, closed: bool = False) -> Endpoint:
    return Endpoint(ident=ident, topic=topic, type=type_name, md5sum="*", queue_size=10, latch=False,
                    registered_ns=at, closed=closed)


def _state(name: str, init_ns: int = 0, **tables) -> NodeState:
    state = NodeState(name=name, init_ns=init_ns)
    for table, endpoints in tables.items():
        getattr(state, table).update({e.ident: e for e in endpoints})
    return state


WORLD = FixedNode("/gazebo", "world", pub=(("/odom", "nav_msgs/msg/Odometry"),),
                  sub=(("/cmd_vel", "geometry_msgs/msg/Twist"),))


def _view(peers: list[Peer], discovery_ns: int = DISCOVERY, limit: int | None = None) -> GraphView:
    extra = {} if limit is None else {"limit": limit}
    return GraphView(discovery_ns, lambda: peers, lambda: (WORLD,), **extra)


def _names(view: GraphView, asker: int, t_ns: int) -> list[str]:
    return [node["name"] for node in json.loads(view.answer(asker, t_ns))["nodes"]]


def test_under_ros2_a_node_sees_others_only_after_both_discovered_them() -> None:
    peers = [Peer(_state("/watcher", 1_000_000_000), True),
             Peer(_state("/talker", 1_200_000_000, publishers=[_endpoint(1, "/chatter", "std_msgs/msg/String",
                                                                          1_200_000_000)]), True)]
    view = _view(peers)
    assert _names(view, 0, 1_400_000_000) == []  # the asker itself has not discovered anyone yet
    assert _names(view, 0, 1_600_000_000) == ["/gazebo"]  # the world is up; the talker is not discovered
    seen = json.loads(view.answer(0, 1_700_000_000))["nodes"]
    assert seen[1] == {"name": "/talker", "kind": "node", "pub": [["/chatter", "std_msgs/msg/String"]], "sub": [],
                       "srv": []}
    assert seen[0]["kind"] == "world" and seen[0]["sub"] == [["/cmd_vel", "geometry_msgs/msg/Twist"]]
    assert _names(view, 1, 1_700_000_000) == ["/gazebo", "/watcher"]  # never the asker itself


def test_under_ros1_registrations_are_seen_at_once_and_closed_or_ended_ones_not() -> None:
    talker = _state("/talker", 0, publishers=[_endpoint(1, "/chatter", "std_msgs/String"),
                                              _endpoint(2, "/old", "std_msgs/String", closed=True)],
                    services=[_endpoint(3, "/switch", "std_srvs/SetBool")])
    peers = [Peer(_state("/watcher"), True), Peer(talker, True), Peer(_state("/ended"), False)]
    node = json.loads(_view(peers, discovery_ns=0).answer(0, 0))["nodes"][1]
    assert node["pub"] == [["/chatter", "std_msgs/String"]] and node["srv"] == [["/switch", "std_srvs/SetBool"]]
    assert _names(_view(peers, discovery_ns=0), 0, 0) == ["/gazebo", "/talker"]


def test_asking_again_reuses_the_encoding_until_a_node_changes_what_others_see_of_it() -> None:
    talker = _state("/talker")
    view = _view([Peer(_state("/watcher"), True), Peer(talker, True)], discovery_ns=0)
    first = view.answer(0, 10)
    assert view.answer(0, 20) is first
    talker.publishers[1] = _endpoint(1, "/chatter", "std_msgs/String")
    talker.graph_version += 1  # as the node link counts a registration
    assert json.loads(view.answer(0, 30))["nodes"][1]["pub"] == [["/chatter", "std_msgs/String"]]


def test_a_view_over_the_frame_cap_drops_the_last_nodes_and_says_it_was_cut() -> None:
    flood = [_endpoint(i, f"/flood/{i:04d}", "std_msgs/msg/String") for i in range(1000)]
    peers = [Peer(_state("/watcher"), True), Peer(_state("/small"), True), Peer(_state("/flood", publishers=flood), True)]
    answer = json.loads(_view(peers, discovery_ns=0, limit=10_000).answer(0, 0))
    assert answer["cut"] is True and [n["name"] for n in answer["nodes"]] == ["/gazebo", "/small"]


def test_an_asker_the_run_does_not_have_is_an_error() -> None:
    with pytest.raises(GraphError, match="no node 3 in a run of 1"):
        _view([Peer(_state("/watcher"), True)]).answer(3, 0)
