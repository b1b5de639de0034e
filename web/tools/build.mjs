// SPDX-License-Identifier: MIT
// build.mjs: bundles the viewer into one static folder (make viewer): index.html, style.css and
// viewer.js, which holds three.js, the runtime's wasm module, the shipped cases
// (tests/golden/*.in.csv), the facet models (examples/render/models) and the star catalogue, so the page needs no network and opens from disk.
// Usage: node web/tools/build.mjs --npm DIR/node_modules --wasm build/wasm/orbillum.wasm --out build/viewer
import fs from 'node:fs';
import path from 'node:path';

const args = Object.fromEntries(process.argv.slice(2).reduce((a, v, i, all) => (v.startsWith('--') ? [...a, [v.slice(2), all[i + 1]]] : a), []));
const ROOT = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..');
const npm = path.resolve(args.npm);
const out = path.resolve(args.out);
const wasm = path.resolve(args.wasm);
const esbuild = (await import(path.join(npm, 'esbuild/lib/main.js'))).default;

// Hipparcos stars to V = 6 as d3-celestial ships them: [RA deg, Dec deg, V, B-V]
function stars() {
  const j = JSON.parse(fs.readFileSync(path.join(npm, 'd3-celestial/data/stars.6.json'), 'utf8'));
  return j.features.map((f) => [f.geometry.coordinates[0], f.geometry.coordinates[1], f.properties.mag, Number(f.properties.bv) || 0.6]);
}

function cases() {
  const dir = path.join(ROOT, 'tests/golden');
  const o = {};
  for (const f of fs.readdirSync(dir).filter((x) => x.endsWith('.in.csv')).sort()) {
    o[f.replace(/\.in\.csv$/, '')] = fs.readFileSync(path.join(dir, f), 'utf8');
  }
  return o;
}

// the facet models of examples/render (OBJ text by name)
function models() {
  const dir = path.join(ROOT, 'examples/render/models');
  const o = {};
  if (!fs.existsSync(dir)) return o;
  for (const f of fs.readdirSync(dir).filter((x) => x.endsWith('.obj')).sort()) {
    o[f.replace(/\.obj$/, '')] = fs.readFileSync(path.join(dir, f), 'utf8');
  }
  return o;
}

const data = {
  name: 'viewer-data',
  setup(b) {
    b.onResolve({ filter: /^viewer-data:/ }, (a) => ({ path: a.path.slice(12), namespace: 'viewer-data' }));
    b.onLoad({ filter: /.*/, namespace: 'viewer-data' }, (a) => {
      if (a.path === 'wasm') return { contents: fs.readFileSync(wasm), loader: 'binary', watchFiles: [wasm] };
      if (a.path === 'stars') return { contents: JSON.stringify(stars()), loader: 'json' };
      if (a.path === 'cases') return { contents: JSON.stringify(cases()), loader: 'json' };
      if (a.path === 'models') return { contents: JSON.stringify(models()), loader: 'json' };
      return null;
    });
  },
};

fs.mkdirSync(out, { recursive: true });
await esbuild.build({
  entryPoints: [path.join(ROOT, 'web/src/viewer.js')],
  bundle: true,
  format: 'iife',
  target: 'es2020',
  minify: true,
  legalComments: 'eof',
  nodePaths: [npm],
  plugins: [data],
  outfile: path.join(out, 'viewer.js'),
  logLevel: 'warning',
});
for (const f of ['index.html', 'style.css']) fs.copyFileSync(path.join(ROOT, 'web', f), path.join(out, f));
const lic = ['three/LICENSE', 'd3-celestial/LICENSE'].filter((f) => fs.existsSync(path.join(npm, f)))
  .map((f) => `==== ${f.split('/')[0]} (bundled in viewer.js)\n${fs.readFileSync(path.join(npm, f), 'utf8')}`).join('\n');
fs.writeFileSync(path.join(out, 'THIRD-PARTY-LICENSES.txt'), lic);
console.log(`viewer: ${path.relative(ROOT, out)}/index.html (viewer.js ${(fs.statSync(path.join(out, 'viewer.js')).size / 1024).toFixed(0)} KiB)`);
