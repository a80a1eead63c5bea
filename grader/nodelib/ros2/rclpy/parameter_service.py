"""rclpy.parameter_service.ParameterService: the six rcl_interfaces services every node serves for its parameters
(``~/describe_parameters`` ... ``~/set_parameters_atomically``), answered by its executor like any service, with
real rclpy's callbacks: ``ros2 param set`` reaches ``set_parameters_atomically`` one parameter at a time."""
from __future__ import annotations

import weakref

from .exceptions import ParameterNotDeclaredException, ParameterUninitializedException
from .parameter import Parameter
from .qos import qos_profile_parameters


class ParameterService:
    def __init__(self, node) -> None:
        from rcl_interfaces.srv import (DescribeParameters, GetParameters, GetParameterTypes, ListParameters,
                                        SetParameters, SetParametersAtomically)
        self._node_weak_ref = weakref.ref(node)
        name = node.get_name()
        # real rclpy's order, which is the order of the node's SERVE frames and of node.services
        for srv_type, suffix, callback in (
                (DescribeParameters, "describe_parameters", self._describe_parameters_callback),
                (GetParameters, "get_parameters", self._get_parameters_callback),
                (GetParameterTypes, "get_parameter_types", self._get_parameter_types_callback),
                (ListParameters, "list_parameters", self._list_parameters_callback),
                (SetParameters, "set_parameters", self._set_parameters_callback),
                (SetParametersAtomically, "set_parameters_atomically", self._set_parameters_atomically_callback)):
            node.create_service(srv_type, f"{name}/{suffix}", callback, qos_profile=qos_profile_parameters)

    def _get_node(self):
        node = self._node_weak_ref()
        if node is None:
            raise ReferenceError("Expected valid node weak reference")
        return node

    def _describe_parameters_callback(self, request, response):
        node = self._get_node()
        for name in request.names:
            try:
                descriptor = node.describe_parameter(name)
            except ParameterNotDeclaredException:
                response.descriptors = node.describe_parameters([])
                return response
            response.descriptors.append(descriptor)
        return response

    def _get_parameters_callback(self, request, response):
        node = self._get_node()
        for name in request.names:
            try:
                param = node.get_parameter(name)
            except (ParameterNotDeclaredException, ParameterUninitializedException):
                response.values = node.get_parameters([])
                return response
            response.values.append(param.get_parameter_value())
        return response

    def _get_parameter_types_callback(self, request, response):
        node = self._get_node()
        for name in request.names:
            try:
                value = node.get_parameter_type(name)
            except ParameterNotDeclaredException:
                response.types = node.get_parameter_types([])
                return response
            response.types.append(value)
        return response

    def _list_parameters_callback(self, request, response):
        from rcl_interfaces.msg import ListParametersResult
        node = self._get_node()
        try:
            response.result = node.list_parameters(request.prefixes, request.depth)
        except (TypeError, ValueError):
            response.result = ListParametersResult()
        return response

    def _set_parameters_callback(self, request, response):
        from .parameter import SetParametersResult
        node = self._get_node()
        for p in request.parameters:
            param = Parameter.from_parameter_msg(p)
            try:
                result = node.set_parameters_atomically([param])
            except ParameterNotDeclaredException as e:
                result = SetParametersResult(successful=False, reason=str(e))
            response.results.append(result)
        return response

    def _set_parameters_atomically_callback(self, request, response):
        from .parameter import SetParametersResult
        node = self._get_node()
        try:
            response.result = node.set_parameters_atomically([Parameter.from_parameter_msg(p)
                                                              for p in request.parameters])
        except ParameterNotDeclaredException as e:
            response.result = SetParametersResult(successful=False, reason=str(e))
        return response
