// The part of Node's Buffer that the log decompressors (@foxglove/wasm-lz4, @foxglove/wasm-zstd) call, for the
// browser bundle of web/vendor-logs.js (esbuild `inject`: it stands for the global Buffer inside the bundle only).
// They copy their output out of the wasm heap: Buffer.allocUnsafe(n), Buffer.from(arrayBuffer), buf.copy(...).
export class Buffer extends Uint8Array {
  static allocUnsafe(size) { return new Buffer(size); }
  static alloc(size) { return new Buffer(size); }
  static from(source, byteOffset, length) {
    if (source instanceof ArrayBuffer) return new Buffer(source, byteOffset ?? 0, length ?? source.byteLength - (byteOffset ?? 0));
    if (ArrayBuffer.isView(source)) return new Buffer(source.buffer.slice(source.byteOffset, source.byteOffset + source.byteLength));
    throw new TypeError('Buffer.from: the browser bundle copies only ArrayBuffers and typed arrays');
  }
  static isBuffer(v) { return v instanceof Buffer; }
  copy(target, targetStart = 0, sourceStart = 0, sourceEnd = this.length) {
    const part = this.subarray(sourceStart, sourceEnd);
    target.set(part, targetStart);
    return part.length;
  }
}
