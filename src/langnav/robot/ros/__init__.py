"""langnav's ROS 2 parts.

* :mod:`~langnav.robot.ros.messages` -- ROS messages as plain dicts <-> langnav types (pure);
* :mod:`~langnav.robot.ros.interfaces` -- message definitions and a CDR encoder (pure);
* :mod:`~langnav.robot.ros.convert` -- those dicts <-> rclpy's generated classes;
* :mod:`~langnav.robot.ros.runtime` -- the rclpy import guard, a private context, a clean shutdown;
* :mod:`~langnav.robot.ros.backend` -- the ``ros2`` robot backend (Nav2 through rclpy);
* :mod:`~langnav.robot.ros.robot_node` -- a robot served as a Nav2-shaped ROS 2 robot;
* :mod:`~langnav.robot.ros.node` -- ``langnav node``: langnav itself as a ROS 2 node.

Only the modules that need rclpy import it, and only when used: importing langnav needs no ROS.
"""
