// Bundles the viewer (src/main.js, three.js and its OrbitControls) into one classic script
// (IIFE): Chromium refuses ES modules from file://. Usage: node build.mjs OUT_DIR
// Writes OUT_DIR/tecido-viewer.js and OUT_DIR/tecido.css.
import { build } from 'esbuild';
import { copyFileSync, mkdirSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const out = process.argv[2] || join(here, 'dist');
mkdirSync(out, { recursive: true });
await build({
  entryPoints: [join(here, 'src/main.js')],
  bundle: true,
  minify: true,
  format: 'iife',
  target: 'es2020',
  legalComments: 'eof',
  outfile: join(out, 'tecido-viewer.js'),
  logLevel: 'warning',
});
copyFileSync(join(here, 'src/tecido.css'), join(out, 'tecido.css'));
