// The web viewer's size (ctest ViewerSize.EveryBundledScene): renders the
// page of EVERY bundled scene (scenes/*.toml) and checks each is at most
// 3 MB, then prints what each page is made of: the bundled JavaScript, the
// timeline, and the embedded GLB by mesh and texture (base64 counted: 4/3
// of the bytes). With --markdown it prints the table docs/interactive.md shows.
// Usage: node viewer_size_test.mjs ROLLSPIN SOURCE_DIR WORK_DIR [--markdown]
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';

const [rollspin, sourceDir, workDir, flag] = process.argv.slice(2);
if (!rollspin || !sourceDir || !workDir) {
  console.error('usage: node viewer_size_test.mjs ROLLSPIN SOURCE_DIR WORK_DIR [--markdown]');
  process.exit(2);
}
const MAX_BYTES = 3 * 1024 * 1024;

// The text of the element <script ... id="ID">…</script>.
function scriptText(html, id) {
  const open = html.indexOf(`id="${id}"`);
  if (open < 0) return '';
  const start = html.indexOf('>', open) + 1;
  return html.slice(start, html.indexOf('</script>', start));
}

// The GLB's bytes by what uses them: each mesh (its accessors' views), each image, the rest.
function glbParts(glb) {
  const jsonLength = glb.readUInt32LE(12);
  const gltf = JSON.parse(glb.subarray(20, 20 + jsonLength).toString('utf8'));
  const owner = new Map();  // buffer view → name
  const claim = (accessor, name) => {
    const view = gltf.accessors[accessor]?.bufferView;
    if (view !== undefined && !owner.has(view)) owner.set(view, name);
  };
  for (const mesh of gltf.meshes ?? [])
    for (const p of mesh.primitives) {
      for (const a of Object.values(p.attributes)) claim(a, mesh.name);
      if (p.indices !== undefined) claim(p.indices, mesh.name);
    }
  for (const image of gltf.images ?? []) owner.set(image.bufferView, `texture ${image.name}`);
  const parts = { json: jsonLength };
  (gltf.bufferViews ?? []).forEach((v, i) => {
    const name = owner.get(i) ?? 'other';
    parts[name] = (parts[name] ?? 0) + v.byteLength;
  });
  return parts;
}

const mb = (bytes) => (bytes / 1e6).toFixed(2);

function measure(scene, dir) {
  const html = path.join(dir, `${scene}.html`);
  const start = Date.now();
  execFileSync(rollspin, ['render', path.join(sourceDir, 'scenes', `${scene}.toml`), '-o', html, '--quiet'], { stdio: 'pipe' });
  const seconds = (Date.now() - start) / 1000;
  const text = fs.readFileSync(html, 'utf8');
  const base64 = scriptText(text, 'rollspin-glb').trim();
  const parts = glbParts(Buffer.from(base64, 'base64'));
  const sorted = Object.entries(parts).sort((a, b) => b[1] - a[1]);
  return { scene, bytes: Buffer.byteLength(text), seconds, glb: base64.length,
    timeline: scriptText(text, 'rollspin-timeline').length, javascript: text.length - base64.length - scriptText(text, 'rollspin-timeline').length,
    largest: sorted.slice(0, 2).map(([name, bytes]) => `${name} ${mb((bytes * 4) / 3)}`) };
}

fs.mkdirSync(workDir, { recursive: true });
const scenes = fs.readdirSync(path.join(sourceDir, 'scenes')).filter((f) => f.endsWith('.toml')).map((f) => f.slice(0, -5)).sort();
const failures = [];
const rows = [];
for (const scene of scenes) {
  const m = measure(scene, workDir);
  rows.push(m);
  if (m.bytes > MAX_BYTES) failures.push(`${scene}: the page is ${m.bytes} bytes, over ${MAX_BYTES}`);
  if (flag !== '--markdown')
    console.log(`${scene}: ${mb(m.bytes)} MB in ${m.seconds.toFixed(2)} s (page and JavaScript ${mb(m.javascript)}, ` +
                `timeline ${mb(m.timeline)}, GLB ${mb(m.glb)}: largest ${m.largest.join(', ')})`);
}
if (flag === '--markdown') {
  console.log('| scene | page MB | GLB (base64) | timeline | largest parts of the GLB (base64 MB) |');
  console.log('| --- | ---: | ---: | ---: | --- |');
  for (const m of rows) console.log(`| ${m.scene} | ${mb(m.bytes)} | ${mb(m.glb)} | ${mb(m.timeline)} | ${m.largest.join(', ')} |`);
}
if (scenes.length < 20) failures.push(`only ${scenes.length} bundled scenes found in ${sourceDir}/scenes`);
for (const f of failures) console.error(`FAIL ${f}`);
console.log(failures.length ? `${failures.length} failures` : `all ${scenes.length} pages within ${MAX_BYTES} bytes`);
process.exit(failures.length ? 1 : 0);
