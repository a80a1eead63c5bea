"""A rospy client of the SetBool server: waits for it, calls it twice (the second fails), prints what it got."""
import rospy
from std_srvs.srv import SetBool

rospy.init_node("switcher")
rospy.wait_for_service("/switch")
print(f"up at {rospy.get_time():.3f}", flush=True)
switch = rospy.ServiceProxy("/switch", SetBool)
print(f"got {switch(True).message} at {rospy.get_time():.3f}", flush=True)
try:
    switch(False)
except rospy.ServiceException as exc:
    print(f"failed: {exc}", flush=True)
