// Where a roscpp node that keeps its topics under ros::NodeHandle("input") and ros::NodeHandle("output") (as
// turtlesim's mimic does) subscribes and publishes, for the remap arguments and ROS_NAMESPACE it is started with.
// Prints one line: the node's name, the subscription's topic, the publication's topic. Built against Debian's roscpp
// by ros1_mimic_real.py; needs a rosmaster (roscpp registers with it on start).
#include <iostream>

#include <geometry_msgs/Twist.h>
#include <ros/ros.h>

namespace {
void ignore(const geometry_msgs::Twist::ConstPtr&) {}
}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "turtle_mimic", ros::init_options::NoRosout);
  ros::NodeHandle heard("input");
  ros::NodeHandle said("output");
  ros::Subscriber subscription = heard.subscribe("pose", 1, ignore);
  ros::Publisher publication = said.advertise<geometry_msgs::Twist>("cmd_vel", 1);
  std::cout << ros::this_node::getName() << " " << subscription.getTopic() << " " << publication.getTopic()
            << std::endl;
  return 0;
}
