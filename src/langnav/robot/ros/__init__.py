"""langnav's ROS side. Importing this package imports none of rclpy, roslibpy or websockets: each
module loads its own when it is used, so a machine without ROS 2 can still use the rosbridge
backend, and one without roslibpy the simulator.

* :mod:`~langnav.robot.ros.messages` -- ROS messages as plain dicts <-> langnav types (pure);
* :mod:`~langnav.robot.ros.interfaces` -- message definitions and a CDR encoder (pure);
* :mod:`~langnav.robot.ros.rosbridge_backend` -- the ``rosbridge`` backend (roslibpy);
* :mod:`~langnav.robot.ros.rosbridge_server` -- langnav's own rosbridge v2 server (websockets);
* :mod:`~langnav.robot.ros.convert` -- message dicts <-> rclpy's generated classes;
* :mod:`~langnav.robot.ros.runtime` -- the rclpy import guard, a private context, a clean shutdown;
* :mod:`~langnav.robot.ros.backend` -- the ``ros2`` backend (Nav2 through rclpy);
* :mod:`~langnav.robot.ros.robot_node` -- a robot served as a Nav2-shaped ROS 2 robot;
* :mod:`~langnav.robot.ros.node` -- ``langnav node``: langnav itself as a ROS 2 node;
* :mod:`~langnav.robot.ros.markers` -- the map analysis as a MarkerArray (pure).
"""
