#!/usr/bin/python3
# Writes the ROS 1 bags of this folder with ROS's own rosbag writer (Debian: apt-get install python3-rosbag
# python3-sensor-msgs; run with the system Python: /usr/bin/python3 make_bags.py, from this folder).
#   intel-{none,lz4,bz2}.bag: chunk compression none / lz4 / bz2, each with
#     /base_scan  sensor_msgs/LaserScan   the 30 FLASER scans of ../intel.log (180 beams, beam i at -pi/2 + i*pi/180;
#                                         range_max 50 m, the sensor's: the log's no-return value 81.83 lies beyond it)
#     /os_cloud   sensor_msgs/PointCloud2 columns 0..63 of ../rellis3d-os1-4x2048.bin as an organised 4 x 64 cloud
#                                         (row = beam, x y z intensity float32 little-endian, point_step 16)
#     /chatter    std_msgs/String         one message (a topic of another type)
# Log time = header stamp = the FLASER record's ipc_timestamp; clouds at 1000 s + k.
import math
import struct
import rosbag
import rospy
from sensor_msgs.msg import LaserScan, PointCloud2, PointField
from std_msgs.msg import String


def intel_scans():
    with open('../intel.log') as f:
        for line in f:
            t = line.split()
            if not t or t[0] != 'FLASER':
                continue
            n = int(t[1])
            yield [float(x) for x in t[2:2 + n]], float(t[2 + n + 6])


def laser_scan(ranges, stamp):
    m = LaserScan()
    m.header.stamp = rospy.Time.from_sec(stamp)
    m.header.frame_id = 'laser'
    n = len(ranges)
    m.angle_min = -math.pi / 2
    m.angle_increment = math.pi / n
    m.angle_max = m.angle_min + (n - 1) * m.angle_increment
    m.range_min = 0.0
    m.range_max = 50.0
    m.ranges = ranges
    return m


def ouster_cloud(k):
    raw = open('../rellis3d-os1-4x2048.bin', 'rb').read()
    beams, cols = 4, 64
    data = b''.join(raw[(c * beams + b) * 16:(c * beams + b) * 16 + 16] for b in range(beams) for c in range(cols))
    m = PointCloud2()
    m.header.stamp = rospy.Time.from_sec(1000 + k)
    m.header.frame_id = 'os_sensor'
    m.height, m.width = beams, cols
    m.fields = [PointField(name, 4 * i, PointField.FLOAT32, 1) for i, name in enumerate(['x', 'y', 'z', 'intensity'])]
    m.is_bigendian = False
    m.point_step, m.row_step = 16, 16 * cols
    m.data = data
    m.is_dense = False
    return m


for compression in ['none', 'lz4', 'bz2']:
    with rosbag.Bag('intel-%s.bag' % compression, 'w', compression=compression, chunk_threshold=8 * 1024) as bag:
        scans = list(intel_scans())
        bag.write('/chatter', String(data='hello'), rospy.Time.from_sec(scans[0][1]))
        for ranges, stamp in scans:
            bag.write('/base_scan', laser_scan(ranges, stamp), rospy.Time.from_sec(stamp))
        for k in range(2):
            bag.write('/os_cloud', ouster_cloud(k), rospy.Time.from_sec(1000 + k))
