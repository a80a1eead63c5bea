#!/usr/bin/env python3
"""Probe 14: parameters at run time through the node's parameter services, as ``ros2 param set`` reaches them: a
set accepted (and its /parameter_events message), a pre-set callback adding a parameter to the set, one refused by
an on-set callback (its reason reaches the setter, and no event), a value of the wrong type, an undeclared name;
get/describe/list, and the services the node serves.

rosgrade does not serve ``~/get_type_description`` (type_description_interfaces is not in its catalog), so the
services are printed without it; the parameter that starts it is listed like any other.
"""
import rclpy
from rcl_interfaces.msg import ParameterEvent, SetParametersResult
from rcl_interfaces.srv import DescribeParameters, GetParameters, GetParameterTypes, ListParameters, SetParameters
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.time import Time


def refuse_negative(params):
    for param in params:
        if param.name == "radius" and param.value < 0.0:
            return SetParametersResult(successful=False, reason="radius must be positive")
    return SetParametersResult(successful=True)


def with_diameter(params):
    return params + [Parameter("diameter", value=2.0 * p.value) for p in params
                     if p.name == "radius" and isinstance(p.value, float)]


rclpy.init()
node = Node("p14_parameters")
node.declare_parameter("radius", 0.5)
node.declare_parameter("diameter", 1.0)
node.add_pre_set_parameters_callback(with_diameter)
node.add_on_set_parameters_callback(refuse_negative)
node.add_post_set_parameters_callback(lambda params: print("post-set", [(p.name, p.value) for p in params]))
setter = Node("p14_setter")
events = []
setter.create_subscription(ParameterEvent, "/parameter_events", events.append, 10)
executor = SingleThreadedExecutor()
executor.add_node(node)
executor.add_node(setter)
print("services", sorted(s.service_name for s in node.services
                         if not s.service_name.endswith("/get_type_description")))
clients = {srv_type: setter.create_client(srv_type, f"/p14_parameters/{name}") for srv_type, name in (
    (SetParameters, "set_parameters"), (GetParameters, "get_parameters"),
    (DescribeParameters, "describe_parameters"), (ListParameters, "list_parameters"),
    (GetParameterTypes, "get_parameter_types"))}
print("wait_for_service", all(client.wait_for_service(timeout_sec=10.0) for client in clients.values()))
for _ in range(2000):  # the event subscription matched (DDS discovery), and sim time running
    if node._parameter_event_publisher.get_subscription_count() and node.get_clock().now().nanoseconds:
        break
    executor.spin_once(timeout_sec=0.01)
print("#REF %.6f" % (node.get_clock().now().nanoseconds / 1e9))


def call(srv_type, request):
    future = clients[srv_type].call_async(request)
    executor.spin_until_future_complete(future, timeout_sec=5.0)
    return future.result()


def spin_for(seconds):
    end = node.get_clock().now().nanoseconds + int(seconds * 1e9)
    while node.get_clock().now().nanoseconds < end:
        executor.spin_once(timeout_sec=0.01)


def set_remotely(name, value):
    request = SetParameters.Request(parameters=[Parameter(name, value=value).to_parameter_msg()])
    results = call(SetParameters, request).results
    spin_for(0.2)
    print("set", name, repr(value), "->", [(r.successful, r.reason) for r in results])


set_remotely("radius", 1.2)
print("radius now", node.get_parameter("radius").value)
print("events", len(events))
event = events[-1]
print("event node", event.node)
print("event new", [p.name for p in event.new_parameters], "deleted", [p.name for p in event.deleted_parameters])
print("event changed", [(p.name, p.value.type, p.value.double_value) for p in event.changed_parameters])
print("event stamped with sim time within 0.4 s before now",
      0 <= (node.get_clock().now() - Time.from_msg(event.stamp)).nanoseconds < 400_000_000)
set_remotely("radius", -1.0)
set_remotely("radius", 1)
set_remotely("speed", 0.3)
print("set atomically with two undeclared names !!", end=" ")
try:
    node.set_parameters_atomically([Parameter("a", value=1), Parameter("b", value=2), Parameter("c", value=3)])
except Exception as exc:
    print(type(exc).__name__, exc)
print("radius now", node.get_parameter("radius").value, "events", len(events))
values = call(GetParameters, GetParameters.Request(names=["radius", "diameter", "use_sim_time"])).values
print("get", [(v.type, v.double_value, v.bool_value) for v in values])
print("get with an undeclared name", list(call(GetParameters, GetParameters.Request(names=["radius", "x"])).values))
print("types", list(call(GetParameterTypes, GetParameterTypes.Request(names=["radius", "use_sim_time"])).types),
      list(call(GetParameterTypes, GetParameterTypes.Request(names=["radius", "x"])).types))
print("get_parameter_type", repr(node.get_parameter_type("radius")))
descriptors = call(DescribeParameters, DescribeParameters.Request(
    names=["radius", "start_type_description_service"])).descriptors
print("describe", [(d.name, d.type, d.read_only, d.dynamic_typing) for d in descriptors])
result = call(ListParameters, ListParameters.Request()).result
print("list", list(result.names), list(result.prefixes))
print("local set", [(r.successful, r.reason) for r in node.set_parameters([Parameter("radius", value=-2.0)])])
node.undeclare_parameter("radius")
spin_for(0.2)
print("events after undeclare", len(events))
rclpy.shutdown()
print("end")
