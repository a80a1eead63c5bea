"""rosgrade's rospy: the ROS 1 Noetic client API for a student's node, run in lockstep with the grader's world."""
from __future__ import annotations

from genpy import Message, SerializationError  # noqa: F401 - rospy re-exports them

from .client import (DEBUG, ERROR, FATAL, INFO, WARN, delete_param, get_param, get_param_names, has_param,
                     init_node, myargv, search_param, set_param, spin, wait_for_message)
from .core import (is_shutdown, is_shutdown_requested, logdebug, logdebug_once, logdebug_throttle,
                   logdebug_throttle_identical, logerr, logerr_once, logerr_throttle, logerr_throttle_identical,
                   logerror, logfatal, logfatal_once, logfatal_throttle, logfatal_throttle_identical, loginfo,
                   loginfo_once, loginfo_throttle, loginfo_throttle_identical, logout, logwarn, logwarn_once,
                   logwarn_throttle, logwarn_throttle_identical, on_shutdown, signal_shutdown)
from .exceptions import (ROSException, ROSInitException, ROSInternalException, ROSInterruptException,
                         ROSSerializationException, ROSTimeMovedBackwardsException)
from .graph import SubscribeListener, get_param_cached, get_published_topics, remap_name
from .msg import AnyMsg
from .names import get_caller_id, get_name, get_namespace, resolve_name
from .rostime import Duration, Time, get_rostime, get_time
from .service import Service, ServiceException, ServiceProxy, wait_for_service
from .timer import Rate, Timer, TimerEvent, sleep
from .topics import Publisher, Subscriber
from std_msgs.msg import Header  # noqa: F401 - rospy.Header

