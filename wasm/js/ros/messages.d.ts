// rtl-wasm/ros: ROS scan messages -> the package's point arrays (pure JavaScript, no WebAssembly, no dependency).
// Messages are plain objects as @foxglove/rosmsg2-serialization, @foxglove/rosmsg-serialization or roslib decode them.
// Bad arguments: TypeError/RangeError whose message starts with the function's name.

/** builtin_interfaces/Time (ROS 2), ROS 1 time, or roslib's JSON time */
export type RosTime = { sec: number; nanosec: number } | { sec: number; nsec: number } | { secs: number; nsecs: number };
export type NumberArray = ArrayLike<number>;

/** sensor_msgs/LaserScan (ROS 1 and ROS 2) */
export interface LaserScanMessage {
  header?: { stamp?: RosTime; frame_id?: string };
  angle_min: number; angle_max: number; angle_increment: number;
  range_min: number; range_max: number;
  ranges: NumberArray; intensities?: NumberArray;
  time_increment?: number; scan_time?: number;
}
/** foxglove.LaserScan */
export interface FoxgloveLaserScanMessage {
  timestamp?: RosTime; frame_id?: string;
  start_angle: number; end_angle: number;
  ranges: NumberArray; intensities?: NumberArray;
}
export interface Scan2D {
  /** x, y per beam in the sensor frame; NaN, NaN (a gap) where the range is NaN, +-inf or outside
   *  [range_min, range_max] (foxglove.LaserScan: not finite or negative) */
  points: Float64Array;
  /** beam angles (rad) */
  angles: Float64Array;
  /** range_max (Infinity for foxglove.LaserScan) */
  maxRange: number;
  /** header stamp in seconds, undefined when the message has none */
  stamp: number | undefined;
  frameId: string;
  /** one per beam, when the message has them */
  intensities?: Float32Array;
}
export function fromLaserScan(msg: LaserScanMessage | FoxgloveLaserScanMessage): Scan2D;

export interface PointFieldMessage { name: string; offset: number; datatype: number; count?: number }
/** sensor_msgs/PointCloud2 (ROS 1 and ROS 2); data may also be roslib's base64 string or a plain byte array */
export interface PointCloud2Message {
  header?: { stamp?: RosTime; frame_id?: string };
  height: number; width: number;
  fields: PointFieldMessage[];
  is_bigendian?: boolean;
  point_step: number; row_step: number;
  data: Uint8Array | ArrayBufferView | ArrayBuffer | string | number[];
  is_dense?: boolean;
}
/** height > 1: readOrganizedLidar's shape (beams = height, row r = beam r, columns = width) */
export interface OrganizedCloudScan {
  beams: number;
  columns: number;
  /** x, y, z column-major: beam b of column c is point c * beams + b; NaN for no return ((0,0,0) or non-finite) */
  points: Float64Array;
  /** per point (NaN when the cloud has no intensity field) */
  intensity: Float32Array;
  /** the cloud's 'ring' field per point, when it has one */
  rings?: Int32Array;
  ring(beam: number): Float64Array;
  column(c: number): Float64Array;
  stamp: number | undefined;
  frameId: string;
}
/** height 1: the points in message order */
export interface UnorganizedCloudScan {
  points: Float64Array;
  count: number;
  intensity?: Float32Array;
  rings?: Int32Array;
  stamp: number | undefined;
  frameId: string;
}
export function fromPointCloud2(msg: PointCloud2Message): OrganizedCloudScan | UnorganizedCloudScan;
