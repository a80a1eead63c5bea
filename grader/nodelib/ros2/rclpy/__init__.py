"""rosgrade's rclpy: the ROS 2 (Jazzy) client API for a student's node, run in lockstep with the grader."""
from __future__ import annotations

from .context import Context
from .parameter import Parameter
from .signals import SignalHandlerOptions, install_signal_handlers, uninstall_signal_handlers
from .task import Future
from .utilities import get_default_context, get_rmw_implementation_identifier, ok  # noqa: F401
from .utilities import shutdown as _shutdown
from .utilities import try_shutdown  # Jazzy's: it leaves the signal handlers installed

__all__ = ["Context", "Future", "Parameter", "SignalHandlerOptions", "create_node", "get_default_context",
           "get_global_executor", "init", "ok", "shutdown", "spin", "spin_once", "spin_until_future_complete",
           "try_shutdown"]


def init(*, args=None, context=None, domain_id=None, signal_handler_options=None) -> None:
    """Initialize ROS communications for a context (the default one unless given), then install the signal handlers
    (by default only for the default context). Returns None, as Jazzy's rclpy (Kilted's returns a context manager)."""
    context = get_default_context() if context is None else context
    if signal_handler_options is None:
        if context is get_default_context():
            signal_handler_options = SignalHandlerOptions.ALL
        else:
            signal_handler_options = SignalHandlerOptions.NO
    context.init(args, domain_id=domain_id)
    install_signal_handlers(signal_handler_options)


__executor = None


def get_global_executor():
    global __executor
    if __executor is None:
        from .executors import SingleThreadedExecutor
        __executor = SingleThreadedExecutor()

        def reset_executor() -> None:
            global __executor
            __executor.shutdown()
            __executor = None
        get_default_context().on_shutdown(reset_executor)
    return __executor


def shutdown(*, context=None, uninstall_handlers=None) -> None:
    """Shut a context down (destroying its nodes); the default context also uninstalls the signal handlers."""
    _shutdown(context=context)
    if uninstall_handlers or (uninstall_handlers is None and (context is None or context is get_default_context())):
        uninstall_signal_handlers()


def create_node(node_name: str, *, context=None, cli_args=None, namespace=None, use_global_arguments=True,
                enable_rosout=True, start_parameter_services=True, parameter_overrides=None,
                allow_undeclared_parameters=False, automatically_declare_parameters_from_overrides=False,
                enable_logger_service=False):
    from .node import Node
    return Node(node_name, context=context, cli_args=cli_args, namespace=namespace,
                use_global_arguments=use_global_arguments, enable_rosout=enable_rosout,
                start_parameter_services=start_parameter_services, parameter_overrides=parameter_overrides,
                allow_undeclared_parameters=allow_undeclared_parameters,
                automatically_declare_parameters_from_overrides=automatically_declare_parameters_from_overrides,
                enable_logger_service=enable_logger_service)


def spin_once(node, *, executor=None, timeout_sec: float | None = None) -> None:
    """Execute one item of work, or wait until the timeout (forever if None or negative; not at all if 0)."""
    executor = get_global_executor() if executor is None else executor
    try:
        executor.add_node(node)
        executor.spin_once(timeout_sec=timeout_sec)
    finally:
        executor.remove_node(node)


def spin(node, executor=None) -> None:
    """Execute work until the executor's context is shut down."""
    executor = get_global_executor() if executor is None else executor
    try:
        executor.add_node(node)
        while executor.context.ok():
            executor._spin_once_impl(None, lambda: False, clock_is_work=False)
    finally:
        executor.remove_node(node)


def spin_until_future_complete(node, future, executor=None, timeout_sec: float | None = None) -> None:
    """Execute work until the future is done, the context is shut down, or the timeout passes."""
    executor = get_global_executor() if executor is None else executor
    node_added = False
    try:
        node_added = executor.add_node(node)
        executor.spin_until_future_complete(future, timeout_sec)
    finally:
        if node_added:
            executor.remove_node(node)
