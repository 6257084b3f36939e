// The web viewer's speed and size (issue 52; not a ctest: docs/performance.md
// records its output). For every bundled scene (or those named):
//   - the export: wall time of `rollspin render SCENE -o NAME.html` (best of 3),
//   - the page's size and what it is made of (three.js bundle, GLB, timeline, scene),
// and for the scenes given with --fps (default lollipop, storyboard, torus):
//   - playback in headless Chromium on SwiftShader at 1280×720, counted by the
//     page itself over 5 s (window.rollspin.measureFps(5)): as the page plays
//     (its render scale adapting to hold 30 frames/s, web/src/frame_pacer.js;
//     the scale it settled at), then at full resolution throughout.
// Usage: node bench/viewer_bench.mjs [--rollspin build/rollspin] [--fps a,b] [SCENE ...]
import { execFileSync } from 'node:child_process';
import { createRequire } from 'node:module';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(name);
  return i < 0 ? fallback : args.splice(i, 2)[1];
};
const rollspin = path.resolve(option('--rollspin', path.join(root, 'build', 'rollspin')));
const fpsScenes = option('--fps', 'lollipop,storyboard,torus').split(',').filter(Boolean);
const scenes = args.length ? args : fs.readdirSync(path.join(root, 'scenes')).filter((f) => f.endsWith('.toml'))
  .map((f) => f.replace(/\.toml$/, '')).sort();
const work = fs.mkdtempSync(path.join(os.tmpdir(), 'rollspin-viewer-bench-'));

// The bytes of each embedded part: the text between a <script ... id="ID"> and its </script>.
function parts(page) {
  const part = (re) => (page.match(re)?.[1] ?? '').length;
  return {
    bundle: part(/<script>([^]*)<\/script>\s*<\/body>/),
    glb: part(/id="rollspin-glb"[^>]*>([^]*?)<\/script>/),
    timeline: part(/id="rollspin-timeline">([^]*?)<\/script>/),
    sceneText: part(/id="rollspin-scene">([^]*?)<\/script>/),
  };
}

function exportScene(scene) {
  const out = path.join(work, `${scene}.html`);
  let best = Infinity;
  for (let k = 0; k < 3; ++k) {
    const start = process.hrtime.bigint();
    execFileSync(rollspin, ['render', scene, '-o', out, '--quiet'], { stdio: 'pipe' });
    best = Math.min(best, Number(process.hrtime.bigint() - start) / 1e9);
  }
  const page = fs.readFileSync(out, 'utf8');
  return { scene, seconds: best, bytes: page.length, ...parts(page), file: out };
}

async function measureFps(files) {
  const { chromium } = createRequire(path.join(root, 'web', 'package.json'))('playwright-core');
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'rollspin-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: '/usr/bin/chromium', headless: true, viewport: { width: 1280, height: 720 },
    args: ['--headless', '--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-quic',
      '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
  await context.route('**/*', (r) => (/^(file|data|blob):/.test(r.request().url()) ? r.continue() : r.abort()));
  const results = [];
  for (const [scene, file] of files) {
    const page = await context.newPage();
    await page.goto(pathToFileURL(file).href);
    await page.evaluate(() => window.rollspin.ready);
    const renderer = await page.evaluate(() => {
      const gl = document.createElement('canvas').getContext('webgl2');
      const info = gl && gl.getExtension('WEBGL_debug_renderer_info');
      return info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : 'unknown';
    });
    // Playing as a viewer does (the render scale adapts to hold 30 frames/s;
    // the scale it settled at, read just before the count ends), then at
    // full resolution throughout.
    const adaptive = await page.evaluate(async () => {
      const counting = window.rollspin.measureFps(5);
      await new Promise((r) => setTimeout(r, 4900));
      const scale = window.rollspin.renderScale();
      return { fps: await counting, scale };
    });
    const full = await page.evaluate(() => {
      window.rollspin.adaptiveResolution = false;
      return window.rollspin.measureFps(5);
    });
    results.push({ scene, fps: adaptive.fps, scale: adaptive.scale, full, renderer });
    await page.close();
  }
  await context.close();
  fs.rmSync(profile, { recursive: true, force: true });
  return results;
}

const kb = (n) => (n / 1024).toFixed(0);
const exports = scenes.map(exportScene);
console.log('| scene | export (s) | page (KiB) | three.js + viewer | GLB (base64) | timeline | scene text |');
console.log('| --- | ---: | ---: | ---: | ---: | ---: | ---: |');
for (const e of exports)
  console.log(`| ${e.scene} | ${e.seconds.toFixed(2)} | ${kb(e.bytes)} | ${kb(e.bundle)} | ${kb(e.glb)} | ${kb(e.timeline)} | ${kb(e.sceneText)} |`);
const files = fpsScenes.map((s) => [s, exports.find((e) => e.scene === s)?.file ?? exportScene(s).file]);
const fps = await measureFps(files);
console.log('\n| scene | frames/s, 1280×720, 5 s | render scale | frames/s at full resolution | renderer |');
console.log('| --- | ---: | ---: | ---: | --- |');
for (const f of fps)
  console.log(`| ${f.scene} | ${f.fps.toFixed(1)} | ${f.scale.toFixed(2)} | ${f.full.toFixed(1)} | ${f.renderer} |`);
fs.rmSync(work, { recursive: true, force: true });
const slow = fps.filter((f) => f.fps < 30), big = exports.filter((e) => e.bytes > 3 * 1024 * 1024 || e.seconds >= 1);
if (slow.length || big.length) {
  console.error(`under 30 fps: ${slow.map((f) => f.scene).join(', ') || 'none'}; over 3 MB or 1 s: ${big.map((e) => e.scene).join(', ') || 'none'}`);
  process.exit(1);
}
