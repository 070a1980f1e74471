// The viewer's entry: the page's data file has set window.TECIDO_VIEW ({kind, ...}); this script
// (a classic script bundled by esbuild, so that it runs from file://) draws it.
import { showRun } from './run_view.js';
import { showTriTri, showPlane, showCcd } from './disagreement_views.js';
import { showSelfCollision } from './selfcollision_view.js';

const views = { run: showRun, tritri: showTriTri, plane: showPlane, ccd: showCcd, selfcollision: showSelfCollision };

function start() {
  const notice = document.getElementById('no-viewer');
  const data = window.TECIDO_VIEW;
  const show = data && views[data.kind];
  if (!show) {
    if (notice) notice.textContent = 'This page has no view data (its .data.js file is missing or of an unknown kind).';
    return;
  }
  if (notice) notice.remove();
  show(data, document.getElementById('stage'));
}

if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start);
else start();
