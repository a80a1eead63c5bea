"""A rospy SetBool server: answers data, fails on False by raising, as a student's handler might."""
import rospy
from std_srvs.srv import SetBool, SetBoolResponse


def handle(request):
    print(f"serve {request.data} at {rospy.get_time():.3f}", flush=True)
    if not request.data:
        raise ValueError("no thanks")
    return SetBoolResponse(success=True, message="done")


rospy.init_node("switch")
rospy.Service("switch", SetBool, handle)
rospy.spin()
