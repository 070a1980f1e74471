// Typed arrays from the page's data file: little-endian float32 / uint32 packed as base64
// (comparisons/view/base64.h writes them). atob + Uint8Array: no fetch, so it works from file://.

function bytes(b64) {
  const s = atob(b64 || '');
  const out = new Uint8Array(s.length);
  for (let i = 0; i < s.length; ++i) out[i] = s.charCodeAt(i);
  return out;
}

export function floats(b64) {
  const b = bytes(b64);
  return new Float32Array(b.buffer, 0, b.length >> 2);
}

export function uints(b64) {
  const b = bytes(b64);
  return new Uint32Array(b.buffer, 0, b.length >> 2);
}

/// A list per frame stored as offsets (frames + 1) and flat items: items of frame f.
export function perFrame(offsets, items, f, width) {
  return items.subarray(offsets[f] * width, offsets[f + 1] * width);
}
