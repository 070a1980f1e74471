// A disagreement entry's labels (comparisons/suites/agreement/replay.h): the engine, its answer,
// the referee's, as text lines in the panel.
import { line } from './ui.js';

export function answerText(a, timeKey) {
  if (!a) return 'no answer';
  const t = timeKey && a.hit && typeof a[timeKey] === 'number' ? `, ${timeKey} = ${a[timeKey].toPrecision(9)}` : '';
  return (a.hit ? 'hit' : 'miss') + t;
}

export function entryName(e, timeKey) {
  return `${e.id} — ${e.engine}: ${answerText(e.answer, timeKey)}; referee: ${answerText(e.referee, timeKey)}`;
}

/// Replaces the panel's entry lines (class "entry") with this entry's.
export function showEntry(parent, e, timeKey) {
  parent.querySelectorAll('.entry').forEach((n) => n.remove());
  line(parent, 'id', e.id, 'entry');
  line(parent, 'engine', e.engine ?? '?', 'entry');
  line(parent, 'its answer', answerText(e.answer, timeKey), 'entry');
  line(parent, "referee's answer", answerText(e.referee, timeKey), 'entry');
}

export function lerp(a, b, t) {
  return [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t];
}

export function flat(points) {
  return new Float32Array(points.flat());
}
