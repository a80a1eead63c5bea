"""Graph test node (rospy): prints whether /chatter is among the published topics every 0.25 s."""
import rospy

rospy.init_node("graph_watcher")
rate = rospy.Rate(4)
while not rospy.is_shutdown():
    topics = dict(rospy.get_published_topics())
    print("%.2f chatter %s" % (rospy.get_time(), topics.get("/chatter")), flush=True)
    rate.sleep()
