// web/link-state.js in Node: the hash of a view and back (the page's parts that need no browser).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { formatHash, parseHash } from '../../web/link-state.js';

test('lesson, parameters, step and source survive the round trip, in order', () => {
  const params = [['sigma', '0.03'], ['delta', '0.05'], ['split', '0']];
  const hash = formatHash('ftls', params, 14, { dataset: 'csail', scan: 11 });
  assert.equal(hash, '#ftls?sigma=0.03&delta=0.05&split=0&src=csail%3A11&at=14');
  assert.deepEqual(parseHash(hash), { id: 'ftls', params, at: 14, src: { dataset: 'csail', scan: 11 }, lecture: false });
  assert.deepEqual(parseHash(hash.slice(1)), parseHash(hash), 'with or without the #');
});

test('a plain lesson hash has no parameters, step or source; an empty one names no lesson', () => {
  assert.deepEqual(parseHash('#dp'), { id: 'dp', params: [], at: null, src: null, lecture: false });
  assert.deepEqual(parseHash(''), { id: '', params: [], at: null, src: null, lecture: false });
  assert.equal(formatHash('dp'), '#dp');
  assert.equal(formatHash('dp', [], null, null), '#dp');
});

test('a step that is not a whole number from 1 and a malformed source are ignored, not guessed', () => {
  for (const at of ['0', '-3', '2.5', 'abc', '']) assert.equal(parseHash(`#dp?at=${at}`).at, null, at);
  for (const src of ['intel', 'intel:', ':3', 'intel:x', 'a b:1']) assert.equal(parseHash(`#dp?src=${encodeURIComponent(src)}`).src, null, src);
});

test('values with reserved characters are encoded and come back unchanged', () => {
  const params = [['name', 'a&b=c #d'], ['unit', 'µm']];
  assert.deepEqual(parseHash(formatHash('tf-tree', params)).params, params);
});

test('lecture mode travels as lecture=1 and comes back; any other value is off', () => {
  const hash = formatHash('dp', [['epsilon', '0.05']], 14, null, true);
  assert.equal(hash, '#dp?epsilon=0.05&lecture=1&at=14');
  assert.deepEqual(parseHash(hash), { id: 'dp', params: [['epsilon', '0.05']], at: 14, src: null, lecture: true });
  assert.equal(formatHash('dp', [], null, null, false), '#dp');
  for (const v of ['0', 'yes', '']) assert.equal(parseHash(`#dp?lecture=${v}`).lecture, false, v);
});
