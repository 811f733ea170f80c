// The base of the package's stateful classes (StreamSegmenter, TfTree, KalmanFilter): each owns one C++ object
// behind an integer handle. dispose() frees it; if the caller forgets, the FinalizationRegistry frees it after the
// wrapper is garbage collected (the held value does not reference the wrapper, so it does not keep it alive).
import { DISPOSE } from './checks.js';

/** The method through which a subclass reads its handle: a module symbol, so it is no member users see. */
export const HANDLE = Symbol('handle');

export class CppObject {
  #h;
  #free;
  #registry;
  #className;
  #disposed;

  /**
   * h: the C++ object's handle (non-zero); free(h) destroys it; registry: a FinalizationRegistry or null; className
   * and noun name the object in the error of a call after dispose() ("TfTree.size: the tree was disposed").
   */
  constructor(h, free, registry, className, noun) {
    this.#h = h;
    this.#free = free;
    this.#registry = registry;
    this.#className = className;
    this.#disposed = `the ${noun} was disposed`;
    registry?.register(this, () => free(h), this);
  }

  /** The handle, for a call of method fn; a TypeError once disposed. */
  [HANDLE](fn) {
    if (this.#h === 0) throw new TypeError(`${this.#className}.${fn}: ${this.#disposed}`);
    return this.#h;
  }

  get disposed() { return this.#h === 0; }

  dispose() {
    if (this.#h === 0) return;
    this.#registry?.unregister(this);
    this.#free(this.#h);
    this.#h = 0;
  }

  [DISPOSE]() { this.dispose(); }
}
