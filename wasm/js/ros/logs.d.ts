// rtl-wasm/logs: MCAP (ROS 2 CDR, ROS 1, JSON messages; chunks none/lz4/zstd) and ROS 1 bags streamed scan by scan.
// Needs the optional peer dependencies @mcap/core, @mcap/support, @foxglove/rosmsg, @foxglove/rosmsg2-serialization,
// @foxglove/rosmsg-serialization and (for bags) @foxglove/rosbag.
import type { OrganizedCloudScan, Scan2D, UnorganizedCloudScan } from './messages.js';

export type LogErrorCode = 'FORMAT' | 'TRUNCATED' | 'CORRUPT' | 'DECODE' | 'UNKNOWN_TOPIC' | 'WRONG_TYPE' | 'MISSING_DEPENDENCY';
/** A failure of the log (not of the arguments): names the file and, where it applies, the topic and the 0-based
 *  index of the message (counted on that topic from the start of the iteration) it stopped at. Every scan before
 *  it has been delivered. */
export class LogError extends Error {
  readonly code: LogErrorCode;
  readonly file: string;
  readonly topic?: string;
  readonly index?: number;
  /** TRUNCATED / CORRUPT in a log read front to back (unindexed): the byte offset of the record it stopped at */
  readonly position?: number;
}
export interface LogTopic {
  name: string;
  /** e.g. 'sensor_msgs/msg/LaserScan' (MCAP schema name) or 'sensor_msgs/LaserScan' (bag) */
  type: string;
  /** messages on the topic; null when an MCAP has no statistics */
  count: number | null;
}
export interface LogScanMeta {
  index: number;
  topic: string;
  /** log time in nanoseconds */
  logTime: bigint;
  /** log time in seconds */
  time: number;
}
export type LogScan = LogScanMeta & (Scan2D | OrganizedCloudScan | UnorganizedCloudScan);
export interface ScanRange {
  /** first log time: seconds (number) or nanoseconds (bigint), inclusive */
  start?: number | bigint;
  /** last log time, inclusive */
  end?: number | bigint;
}
export interface Log extends AsyncDisposable {
  format: 'mcap' | 'bag';
  file: string;
  topics: LogTopic[];
  /** set when a log has no usable index (e.g. a cut-off recording) and is read front to back: topics count the
   *  complete messages; scans() delivers them (a bag's in file order), then the LogError of where the file stops */
  unindexed?: { reason: string; stoppedBy?: string };
  /** Scans of a LaserScan or PointCloud2 topic in log-time order. Throws at once: TypeError/RangeError ("scans: ")
   *  for bad arguments, LogError UNKNOWN_TOPIC / WRONG_TYPE. */
  scans(topic: string, range?: ScanRange): AsyncIterableIterator<LogScan>;
  close(): Promise<void>;
}
export type LogSource = string | Blob | ArrayBuffer | ArrayBufferView | { read: Function; stat: Function };
/** Opens a log from a path or fs.promises FileHandle (Node), a Blob/File (browsers), or bytes in memory. A path
 *  is closed by close(); a handle or Blob stays the caller's. */
export function openLog(source: LogSource, options?: { name?: string }): Promise<Log>;
