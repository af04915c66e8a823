"""The ROS side of langnav: the ``rosbridge`` backend (roslibpy) and langnav's own rosbridge v2
server (websockets), next to the ROS 2 (rclpy) backend. Importing this package imports none of
roslibpy, websockets or rclpy: each module loads its own when it is used, so a machine without
ROS 2 can still use the rosbridge backend, and one without roslibpy the simulator."""
