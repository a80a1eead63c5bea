"""The parameter tree (rosmaster's semantics, shared by the grader and the nodes) and the run's server: what it
records, and what it forwards to each node, which, replayed on that node's copy, gives the server's tree."""
from __future__ import annotations

import random

import pytest

from grader.nodelib.common import rosgrade_params as tree
from grader.runtime.param_server import GRADER, WORLD, ParamServer, change_text, initial_tree


def test_setting_below_a_leaf_turns_it_into_a_namespace() -> None:
    t = {"a": 1}
    tree.set_value(t, "/a/b", 2)
    assert t == {"a": {"b": 2}}


def test_setting_a_dict_replaces_the_namespace_and_keeps_a_copy() -> None:
    t = {"a": {"old": 1}}
    value = {"b": [1, 2]}
    tree.set_value(t, "/a", value)
    value["b"].append(3)
    assert t == {"a": {"b": [1, 2]}}


def test_the_root_takes_only_a_dict_and_keeps_its_identity() -> None:
    t = {"a": 1}
    same = t
    tree.set_value(t, "/", {"b": 2})
    assert same == {"b": 2}
    with pytest.raises(TypeError, match="cannot set root of parameter tree to non-dictionary"):
        tree.set_value(t, "/", 3)


def test_deleting_a_namespace_deletes_everything_under_it_and_a_missing_name_is_a_key_error() -> None:
    t = {"a": {"b": {"c": 1}, "d": 2}}
    tree.delete(t, "/a/b")
    assert t == {"a": {"d": 2}}
    for missing in ("/a/b", "/a/d/e", "/"):
        with pytest.raises(KeyError):
            tree.delete(t, missing)


def test_lookup_reads_leaves_and_namespaces() -> None:
    t = {"a": {"b": 1}}
    assert tree.lookup(t, "/a") == {"b": 1} and tree.lookup(t, "/a/b") == 1 and tree.lookup(t, "/") is t
    with pytest.raises(KeyError):
        tree.lookup(t, "/a/b/c")


def test_is_under_compares_whole_name_parts() -> None:
    assert tree.is_under("/a/b", "/a") and tree.is_under("/a", "/a") and tree.is_under("/x", "/")
    assert not tree.is_under("/ab", "/a") and not tree.is_under("/a", "/a/b")


def test_the_initial_tree_holds_use_sim_time_and_every_nodes_params_later_over_earlier() -> None:
    got = initial_tree(False, [{"/a/b": 1, "/c": 2}, {"/c": 3, "d": {"e": 4}}])
    assert got == {"use_sim_time": False, "a": {"b": 1}, "c": 3, "d": {"e": 4}}


def _server(start: dict | None = None) -> tuple[ParamServer, list[tuple[str, object]]]:
    records: list[tuple[str, object]] = []
    server = ParamServer(start or {}, lambda text, author: records.append((text, author)))
    return server, records


def test_changes_before_start_are_part_of_the_start_record_and_later_ones_are_recorded_each() -> None:
    server, records = _server({"use_sim_time": True})
    server.set("/turtlesim/background_r", 69)  # the world's start
    server.start()
    server.set("/x", [1], author=0)
    assert server.delete("/x", author=1) and not server.delete("/x", author=1)
    assert records == [
        ('{"op":"set","name":"/","value":{"use_sim_time":true,"turtlesim":{"background_r":69}}}', GRADER),
        ('{"op":"set","name":"/x","value":[1]}', 0), ('{"op":"delete","name":"/x"}', 1)]


def test_a_node_is_sent_what_others_changed_since_it_last_ran_never_its_own() -> None:
    server, _ = _server()
    server.start()
    server.joined(0)
    server.set("/early", 1, author=WORLD)
    server.joined(1)  # its START had /early
    server.set("/a", 1, author=0)
    server.set("/b", 2, author=1)
    assert server.take(0) == [("/early", 1), ("/b", 2)]
    assert server.take(1) == [("/a", 1)]
    assert server.take(0) == [] and server.take(5) == []


def test_a_change_replaces_the_forwarded_changes_on_its_name_and_under_it() -> None:
    server, _ = _server()
    server.start()
    server.joined(0)
    for name, value in (("/a/b", 1), ("/ab", 2), ("/a/c", 3), ("/a", {"d": 4}), ("/a/d", 5)):
        server.set(name, value, author=1)
    assert server.take(0) == [("/ab", 2), ("/a", {"d": 4}), ("/a/d", 5)]


def test_a_deletion_forwarded_without_the_change_that_made_its_namespace_leaves_the_namespace() -> None:
    copy = {}
    tree.apply(copy, [("/a/b", None)])  # /a/b was set then deleted: only the deletion is forwarded
    assert copy == {"a": {}}


def _random_change(rng: random.Random, truth: dict) -> tuple[str, object] | None:
    """A change a rospy node could make now: a set anywhere, or the deletion of a name that exists."""
    name = "/" + "/".join(rng.choice("abc") for _ in range(rng.randint(1, 3)))
    if rng.random() < 0.35:
        try:
            tree.lookup(truth, name)
        except KeyError:
            return None
        return name, None
    value = rng.choice([rng.randint(0, 9), {"a": rng.randint(0, 9)}, {}, [1, "x"]])
    return name, value


@pytest.mark.parametrize("seed", range(40))
def test_every_nodes_copy_is_the_servers_tree_when_it_runs(seed: int) -> None:
    """Three nodes take turns changing parameters; each starts its turn with the batch's changes applied."""
    rng = random.Random(seed)
    server, _ = _server({"use_sim_time": True})
    server.start()
    copies = [{} for _ in range(3)]
    for index, copy in enumerate(copies):
        tree.set_value(copy, "/", server.tree)
        server.joined(index)
    for turn in range(60):
        index = rng.randrange(3)
        tree.apply(copies[index], server.take(index))
        assert copies[index] == server.tree, (seed, turn)
        for _ in range(rng.randint(0, 4)):
            change = _random_change(rng, server.tree)
            if change is None:
                continue
            name, value = change
            if value is None:
                tree.delete(copies[index], name)
                server.delete(name, author=index)
            else:
                tree.set_value(copies[index], name, value)
                server.set(name, value, author=index)


def test_recorded_changes_are_json_text() -> None:
    assert change_text("/a", {"b": 1.5}) == '{"op":"set","name":"/a","value":{"b":1.5}}'
    assert change_text("/a", None) == '{"op":"delete","name":"/a"}'
