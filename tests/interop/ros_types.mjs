// ROS 2 message definitions (common_interfaces, comments dropped) in the "ros2msg" encoding that
// rosbag2 stores, and the messages the interop writers put in their bags: written from these
// texts by @foxglove/rosmsg2-serialization, independently of littermap's own codec.
import { parse } from "@foxglove/rosmsg";
import { MessageReader, MessageWriter } from "@foxglove/rosmsg2-serialization";

const SEP = "=".repeat(80);
const msg = (name, text) => `${SEP}\nMSG: ${name}\n${text}`;
const time = msg("builtin_interfaces/Time", "int32 sec\nuint32 nanosec\n");
const header = msg("std_msgs/Header", "builtin_interfaces/Time stamp\nstring frame_id\n");

export const definitions = {
  "sensor_msgs/msg/LaserScan":
    "std_msgs/Header header\nfloat32 angle_min\nfloat32 angle_max\nfloat32 angle_increment\n" +
    "float32 time_increment\nfloat32 scan_time\nfloat32 range_min\nfloat32 range_max\n" +
    "float32[] ranges\nfloat32[] intensities\n" + header + time,
  "nav_msgs/msg/Odometry":
    "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/PoseWithCovariance pose\n" +
    "geometry_msgs/TwistWithCovariance twist\n" + header + time +
    msg("geometry_msgs/PoseWithCovariance", "Pose pose\nfloat64[36] covariance\n") +
    msg("geometry_msgs/Pose", "Point position\nQuaternion orientation\n") +
    msg("geometry_msgs/Point", "float64 x\nfloat64 y\nfloat64 z\n") +
    msg("geometry_msgs/Quaternion", "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n") +
    msg("geometry_msgs/TwistWithCovariance", "Twist twist\nfloat64[36] covariance\n") +
    msg("geometry_msgs/Twist", "Vector3 linear\nVector3 angular\n") +
    msg("geometry_msgs/Vector3", "float64 x\nfloat64 y\nfloat64 z\n"),
};

export const qos =
  "- history: 1\n  depth: 10\n  reliability: 2\n  durability: 2\n  deadline:\n    sec: 9223372036\n" +
  "    nsec: 854775807\n  lifespan:\n    sec: 9223372036\n    nsec: 854775807\n  liveliness: 1\n" +
  "  liveliness_lease_duration:\n    sec: 9223372036\n    nsec: 854775807\n" +
  "  avoid_ros_namespace_conventions: false";

export function writerFor(type) {
  return new MessageWriter(parse(definitions[type], { ros2: true }));
}

export function readerFor(definition) {
  return new MessageReader(parse(definition, { ros2: true }));
}

const START_NS = 1_700_000_000_000_000_000n;

// 60 laser scans at 10 Hz on /scan_front and 150 odometry messages at 25 Hz on
// /odometry/filtered, recorded in time order. Values are simple functions of the index, so
// the C++ side checks them without a copy of this list.
export function interopMessages() {
  const scan = writerFor("sensor_msgs/msg/LaserScan");
  const odom = writerFor("nav_msgs/msg/Odometry");
  const out = [];
  const stamp = (ns) => ({ sec: Number(ns / 1_000_000_000n), nanosec: Number(ns % 1_000_000_000n) });
  for (let i = 0; i < 60; i++) {
    const t = START_NS + BigInt(i) * 100_000_000n;
    const ranges = Float32Array.from({ length: 181 }, (_, k) => 1 + 0.01 * k + 0.001 * i);
    out.push({
      topic: "/scan_front", type: "sensor_msgs/msg/LaserScan", logTime: t,
      data: scan.writeMessage({
        header: { stamp: stamp(t), frame_id: "laser_front" },
        angle_min: -Math.PI / 2, angle_max: Math.PI / 2, angle_increment: Math.PI / 180,
        time_increment: 0, scan_time: 0.1, range_min: 0.05, range_max: 30,
        ranges, intensities: new Float32Array(0),
      }),
    });
  }
  for (let i = 0; i < 150; i++) {
    const t = START_NS + BigInt(i) * 40_000_000n + 1_000n;
    out.push({
      topic: "/odometry/filtered", type: "nav_msgs/msg/Odometry", logTime: t,
      data: odom.writeMessage({
        header: { stamp: stamp(t), frame_id: "odom" }, child_frame_id: "base_link",
        pose: { pose: { position: { x: 0.02 * i, y: 0, z: 0 }, orientation: { x: 0, y: 0, z: 0, w: 1 } },
                covariance: new Float64Array(36) },
        twist: { twist: { linear: { x: 0.5, y: 0, z: 0 }, angular: { x: 0, y: 0, z: 0 } },
                 covariance: new Float64Array(36) },
      }),
    });
  }
  out.sort((a, b) => (a.logTime < b.logTime ? -1 : a.logTime > b.logTime ? 1 : 0));
  return out;
}
