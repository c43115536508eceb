// Builds dist/: the bundled app, its page and styles, and uPlot's stylesheet. The C++ back ends
// serve dist/ as static files, so everything the page needs must land here.
import { build } from 'esbuild';
import { copyFile, mkdir, rm } from 'node:fs/promises';
import { fileURLToPath } from 'node:url';
import path from 'node:path';

const here = path.dirname(fileURLToPath(import.meta.url));
const dist = path.join(here, 'dist');

await rm(dist, { recursive: true, force: true });
await mkdir(dist, { recursive: true });
// Two pages: the dashboard (app.js) and duet studio's page (studio.js), bundled alike.
const pages = [
  ['src/main.js', 'app.js'],
  ['src/studio/main.js', 'studio.js'],
];
for (const [entry, bundle] of pages) {
  await build({
    entryPoints: [path.join(here, entry)],
    outfile: path.join(dist, bundle),
    bundle: true,
    minify: !process.env.DUET_NO_MINIFY, // DUET_NO_MINIFY=1 keeps names readable in CPU profiles
    sourcemap: true,
    format: 'iife',
    target: ['es2022'], // Chromium on the board and every current desktop browser
    logLevel: 'warning',
  });
}
const copies = [
  ['src/index.html', 'index.html'],
  ['src/theme.css', 'theme.css'],
  ['src/charts.css', 'charts.css'],
  ['src/style.css', 'style.css'],
  ['node_modules/uplot/dist/uPlot.min.css', 'uPlot.min.css'],
  ['src/studio.html', 'studio.html'],
  ['src/studio/studio.css', 'studio.css'],
  ['src/studio/diagram/diagram.css', 'diagram.css'],
  ['src/studio/panels/panels.css', 'panels.css'],
];
for (const [from, to] of copies) await copyFile(path.join(here, from), path.join(dist, to));
console.log(`built ${path.relative(process.cwd(), dist) || '.'}/`);
