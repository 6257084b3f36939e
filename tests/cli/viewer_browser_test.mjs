// The web viewer in a browser (ctest Browser.Viewer, label "browser"): for
// several bundled scenes, `rollspin render SCENE -o NAME.html`, then Debian's
// Chromium (driven by npm playwright-core, no browser download) opens the
// page from file:// with every other request failing the test, and checks
//   - state() against `rollspin timeline --at-s` at 50 random s (1e-6),
//   - the screenshot: the ball and the Bloch sphere drawn (saved as PNG),
//   - keyboard scrubbing moves s, chapters jump to their segment's start,
//   - the clip's clock: sAt(t) against the arc length of every key of the
//     GLB's `roll` animation (`rollspin export`: the frame clock's s at the
//     key's time), and playing advances the clock at about 1 s a second,
//   - the shown surface (state().surface) in every chapter of a storyboard
//     on two surfaces, against the chapter and the GLB's surface nodes,
//   - the page's size (≤ 3 MB), its scene text and generator,
//   - the cheap surfaces (web/src/surface_cost.js: closed ones culled, the
//     shadow's lookups only near the ball) draw the ball view as every
//     triangle drawn both sides with the lookups does, at three s.
// Usage: node viewer_browser_test.mjs ROLLSPIN SOURCE_DIR WORK_DIR
import { execFileSync } from 'node:child_process';
import { createRequire } from 'node:module';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const [rollspin, sourceDir, workDir] = process.argv.slice(2);
if (!rollspin || !sourceDir || !workDir) {
  console.error('usage: node viewer_browser_test.mjs ROLLSPIN SOURCE_DIR WORK_DIR');
  process.exit(2);
}
const CHROMIUM = '/usr/bin/chromium';
let chromium;
try {
  ({ chromium } = createRequire(path.resolve(sourceDir, 'web', 'package.json'))('playwright-core'));
} catch (e) {
  console.log(`SKIP: ${e.message.split('\n')[0]}`);
  console.log('SKIP: web/node_modules/playwright-core is missing (npm ci in web/, or bash scripts/install-deps.sh)');
  process.exit(77);
}
if (!fs.existsSync(CHROMIUM)) {
  console.log(`SKIP: ${CHROMIUM} is missing (apt-get install chromium, or bash scripts/install-deps.sh)`);
  process.exit(77);
}

// Bundled scenes: a flat circle, a storyboard with chapters, a curved
// surface, two surfaces, a closed one (the whole sphere).
const SCENES = ['lollipop', 'storyboard', 'torus', 'torus-to-floor', 'berry'];
const SAMPLES = 50;
const TOLERANCE = 1e-6;
const MAX_BYTES = 3 * 1024 * 1024;
const CHROMIUM_ARGS = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync'];

const failures = [];
function check(ok, message) {
  if (!ok) failures.push(message);
  return ok;
}

// A small seeded generator, so a failure can be rerun with the same s.
function random(seed) {
  let x = seed >>> 0;
  return () => ((x = (Math.imul(x, 1664525) + 1013904223) >>> 0) / 4294967296);
}

function readTimelineCsv(file) {
  const lines = fs.readFileSync(file, 'utf8').split('\n').filter((l) => l && !l.startsWith('#'));
  const header = lines[0].split(',');
  return lines.slice(1).map((l) => Object.fromEntries(l.split(',').map((v, i) => [header[i], Number(v)])));
}

function rotate(q, v) {
  const [w, x, y, z] = q;
  const cx = y * v[2] - z * v[1], cy = z * v[0] - x * v[2], cz = x * v[1] - y * v[0];
  return [v[0] + 2 * (w * cx + y * cz - z * cy), v[1] + 2 * (w * cy + z * cx - x * cz),
    v[2] + 2 * (w * cz + x * cy - y * cx)];
}

const largestGap = (a, b) => Math.max(...a.map((v, i) => Math.abs(v - b[i])));

// state() at 50 random s (and every chapter start) against the CLI's rows at the same s.
async function checkStates(page, scene, dir) {
  const { length, chapters } = await page.evaluate(() => ({ length: window.rollspin.length, chapters: window.rollspin.chapters }));
  const next = random(scene.length * 7919 + 17);
  const arcs = [0, length, ...chapters.map((c) => c.start)];
  while (arcs.length < SAMPLES + 2 + chapters.length) arcs.push(next() * length);
  const arcFile = path.join(dir, `${scene}.s.txt`), csv = path.join(dir, `${scene}.csv`);
  fs.writeFileSync(arcFile, arcs.map((s) => s.toPrecision(17)).join('\n') + '\n');
  execFileSync(rollspin, ['timeline', scene, '--at-s', arcFile, '-o', csv], { stdio: 'pipe' });
  const rows = readTimelineCsv(csv);
  check(rows.length === arcs.length, `${scene}: the CLI wrote ${rows.length} rows for ${arcs.length} arc lengths`);
  const marker = [rows[0].nx, rows[0].ny, rows[0].nz];  // no bundled scene sets ball.marker: n(0)
  const states = await page.evaluate((list) => list.map((s) => {
    window.rollspin.seek(s);
    return window.rollspin.state();
  }), rows.map((r) => r.s));
  let worst = 0;
  rows.forEach((row, i) => {
    const q = [row.qw, row.qx, row.qy, row.qz], st = states[i];
    const gap = Math.max(largestGap(st.quaternion, q), largestGap(st.bloch, rotate(q, marker)), Math.abs(st.s - row.s));
    worst = Math.max(worst, gap);
    check(gap <= TOLERANCE, `${scene}: at s = ${row.s} state() is off the timeline by ${gap.toExponential(2)}`);
    check(st.segment === (row.segment ?? 0), `${scene}: at s = ${row.s} segment ${st.segment}, the CLI ${row.segment}`);
  });
  console.log(`${scene}: ${rows.length} arc lengths, largest difference from the CLI ${worst.toExponential(2)}`);
}

// The screenshot: both views drawn (not blank), the ball and the Bloch sphere where the cameras put them.
async function checkPixels(page, scene, dir) {
  const shot = path.join(dir, `${scene}.png`);
  await page.screenshot({ path: shot });
  // (drawNow: the canvases keep no drawing buffer past the frame's task.)
  const views = await page.evaluate(() => (window.rollspin.drawNow(), window.rollspin.views()).map((v) => {
    const canvas = document.querySelector(`#${v.element} canvas`);
    const probe = document.createElement('canvas');
    probe.width = canvas.width;
    probe.height = canvas.height;
    const ctx = probe.getContext('2d');
    ctx.drawImage(canvas, 0, 0);
    const pixels = ctx.getImageData(0, 0, probe.width, probe.height).data;
    const colours = new Set();
    let drawn = 0;
    for (let i = 0; i < pixels.length; i += 4) {
      if (pixels[i + 3] > 0) drawn += 1;
      colours.add((pixels[i] >> 3) << 10 | (pixels[i + 1] >> 3) << 5 | (pixels[i + 2] >> 3));
    }
    // The object's centre, from page pixels to canvas pixels.
    const box = canvas.getBoundingClientRect(), scale = canvas.width / box.width;
    const x = Math.round((v.centre[0] - box.left) * scale), y = Math.round((v.centre[1] - box.top) * scale);
    const at = ctx.getImageData(Math.min(Math.max(x, 0), canvas.width - 1), Math.min(Math.max(y, 0), canvas.height - 1), 1, 1).data;
    return { name: v.name, share: drawn / (pixels.length / 4), colours: colours.size, centreAlpha: at[3] };
  }));
  for (const v of views) {
    check(v.share > 0.02, `${scene}: the ${v.name} view is blank (${(100 * v.share).toFixed(2)} % drawn; see ${shot})`);
    check(v.colours > 50, `${scene}: the ${v.name} view has only ${v.colours} colours (see ${shot})`);
    check(v.centreAlpha > 0, `${scene}: nothing drawn at the ${v.name}'s centre (see ${shot})`);
  }
  console.log(`${scene}: screenshot ${shot}: ${views.map((v) => `${v.name} ${(100 * v.share).toFixed(1)} % drawn, ${v.colours} colours`).join('; ')}`);
}

// The ball view drawn with window.rollspin.cheapSurfaces on and off: within
// 2 levels a channel, but for a few pixels where a silhouette's back faces
// used to win (at most 1 in 10,000 of the view).
async function checkCheapSurfaces(page, scene) {
  const length = await page.evaluate(() => window.rollspin.length);
  for (const s of [0.13, 0.5, 0.87].map((f) => f * length)) {
    const differing = await page.evaluate((at) => {
      const [cheap, full] = [true, false].map((on) => {
        window.rollspin.cheapSurfaces = on;
        window.rollspin.seek(at);
        window.rollspin.drawNow();
        const canvas = document.querySelector('#ball-view canvas');
        const probe = document.createElement('canvas');
        probe.width = canvas.width;
        probe.height = canvas.height;
        const ctx = probe.getContext('2d');
        ctx.drawImage(canvas, 0, 0);
        return ctx.getImageData(0, 0, probe.width, probe.height).data;
      });
      window.rollspin.cheapSurfaces = true;
      let count = 0;
      for (let i = 0; i < cheap.length; i += 4) {
        let gap = 0;
        for (let c = 0; c < 4; ++c) gap = Math.max(gap, Math.abs(cheap[i + c] - full[i + c]));
        if (gap > 2) count += 1;
      }
      return { count, pixels: cheap.length / 4 };
    }, s);
    check(differing.count <= differing.pixels / 10000,
          `${scene}: at s = ${s.toFixed(3)} the cheap surfaces differ from the full ones in ${differing.count} pixels`);
    if (s === 0.13 * length) console.log(`${scene}: cheap surfaces: ${differing.count} of ${differing.pixels} pixels differ at s = ${s.toFixed(3)}`);
  }
}

async function checkKeys(page, scene) {
  const s = () => page.evaluate(() => window.rollspin.state().s);
  const length = await page.evaluate(() => window.rollspin.length);
  await page.evaluate(() => window.rollspin.seek(0));
  await page.focus('#ball-view');
  for (let k = 0; k < 3; ++k) await page.keyboard.press('ArrowRight');
  check(Math.abs((await s()) - 3 * length / 200) < 1e-9 * length, `${scene}: three → keys moved s to ${await s()}`);
  await page.keyboard.press('ArrowLeft');
  check(Math.abs((await s()) - 2 * length / 200) < 1e-9 * length, `${scene}: ← did not step s back`);
  await page.keyboard.press('End');
  check((await s()) === length, `${scene}: End did not go to the end`);
  await page.keyboard.press('Home');
  check((await s()) === 0, `${scene}: Home did not go to the start`);
  await page.keyboard.press(' ');
  await page.waitForFunction(() => window.rollspin.state().s > 0, null, { timeout: 5000 }).catch(() => {});
  await page.keyboard.press(' ');
  check((await s()) > 0, `${scene}: space did not play`);
  const playing = await page.evaluate(() => document.getElementById('play').getAttribute('aria-pressed'));
  check(playing === 'false', `${scene}: space did not pause again`);
}

async function checkChapters(page, scene) {
  const chapters = await page.evaluate(() => window.rollspin.chapters);
  if (scene === 'storyboard') check(chapters.length >= 2, `${scene}: ${chapters.length} chapters`);
  const buttons = page.locator('#chapters button');
  check((await buttons.count()) === chapters.length, `${scene}: ${await buttons.count()} chapter buttons`);
  for (let k = chapters.length - 1; k >= 0; --k) {
    await page.evaluate(() => window.rollspin.seek(window.rollspin.length / 3));
    await buttons.nth(k).click();
    const st = await page.evaluate(() => window.rollspin.state());
    check(st.s === chapters[k].start, `${scene}: chapter ${chapters[k].number} went to s = ${st.s}, not ${chapters[k].start}`);
    if (chapters[k].end > chapters[k].start)
      check(st.segment === chapters[k].number, `${scene}: chapter ${chapters[k].number} shows segment ${st.segment}`);
  }
  // Played through on the clip's clock, every chapter's caption shows in its
  // time, a hold's too (while s rests where the motion before it ended).
  // One animation frame a sample: the page's own frame callback (it draws
  // and sets the caption) was queued in the frame before, so it runs before
  // ours in the next one. Headless Chromium gives 60 frames a second: two
  // frames a sample took 13.4 s a scene, two thirds of the whole test. The
  // page is drawn small meanwhile: the captions do not depend on its size,
  // and at 1280×720 SwiftShader took about 27 ms a frame (11 s a scene).
  const size = page.viewportSize();
  await page.setViewportSize({ width: 480, height: 270 });
  const shown = await page.evaluate(async () => {
    const v = window.rollspin, seen = new Set();
    for (let i = 0; i <= 400; ++i) {
      v.seekTime((v.duration * i) / 400);
      await new Promise((r) => requestAnimationFrame(r));
      seen.add(document.getElementById('caption').textContent);
    }
    return [...seen];
  });
  await page.setViewportSize(size);
  for (const c of chapters)
    if (c.caption) check(shown.includes(c.caption), `${scene}: chapter ${c.number}'s caption "${c.caption}" never shows in time`);
  // Each motion's ball view looks from its segment's angles (camera keys laid
  // over the earlier segments'), from Reset on with no orbit in between.
  await page.locator('#reset').click();
  for (const c of chapters.filter((ch) => ch.end > ch.start)) {
    const eye = await page.evaluate(async (s) => {
      window.rollspin.seek(s);
      await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
      return window.rollspin.views()[0].eye;
    }, 0.5 * (c.start + c.end));
    const [az, el] = c.viewDeg.map((d) => (d * Math.PI) / 180);
    const want = [Math.cos(el) * Math.cos(az), Math.cos(el) * Math.sin(az), Math.sin(el)];
    const off = Math.max(...want.map((w, i) => Math.abs(w - eye[i])));
    check(off < 1e-6, `${scene}: chapter ${c.number} looks from [${eye}], not its angles ${c.viewDeg} (off by ${off})`);
  }
}

// The GLB's JSON chunk and an accessor's floats (tightly packed, as the exporter writes them).
function readGlb(file) {
  const glb = fs.readFileSync(file);
  const jsonLength = glb.readUInt32LE(12);
  const gltf = JSON.parse(glb.subarray(20, 20 + jsonLength).toString('utf8'));
  const bin = glb.subarray(20 + jsonLength + 8);
  const floats = (index) => {
    const a = gltf.accessors[index], v = gltf.bufferViews[a.bufferView];
    const width = { SCALAR: 1, VEC3: 3, VEC4: 4 }[a.type];
    const out = new Float32Array(a.count * width);
    Buffer.from(out.buffer).set(bin.subarray(v.byteOffset + (a.byteOffset ?? 0), v.byteOffset + (a.byteOffset ?? 0) + out.byteLength));
    return Array.from(out);
  };
  return { gltf, floats };
}

// The clock: at every key of the exported `roll`, the page's sAt(t) is the key's arc length (float32),
// and timeAt(s) shows that s again; then playing moves the clip's time at the wall clock's pace.
async function checkClock(page, scene, dir) {
  const glbFile = path.join(dir, `${scene}.glb`);
  execFileSync(rollspin, ['export', scene, '-o', glbFile, '--no-metadata'], { stdio: 'pipe' });
  const { gltf, floats } = readGlb(glbFile);
  const ball = gltf.nodes.findIndex((n) => n.name === 'ball');
  const roll = gltf.animations.find((a) => a.name === 'roll');
  const channel = roll.channels.find((c) => c.target.node === ball && c.target.path === 'rotation');
  const times = floats(roll.samplers[channel.sampler].input);
  const arcs = floats(gltf.nodes[ball].extras.rollspin.arc_length);
  const { gaps, length, duration } = await page.evaluate((keys) => ({
    gaps: keys.map(([t, s]) => [Math.abs(window.rollspin.sAt(t) - s), Math.abs(window.rollspin.sAt(window.rollspin.timeAt(s)) - s)]),
    length: window.rollspin.length, duration: window.rollspin.duration }), times.map((t, k) => [t, arcs[k]]));
  const tolerance = 2e-7 * Math.max(1, length);  // float32 arc lengths
  const worst = Math.max(...gaps.flat());
  check(worst <= tolerance, `${scene}: the page's clock is off the export's keys by ${worst.toExponential(2)} (of L = ${length})`);
  check(Math.abs(duration - times[times.length - 1]) <= 1e-5 * duration,
        `${scene}: the page's clip lasts ${duration} s, the export's ${times[times.length - 1]} s`);
  console.log(`${scene}: clock at ${times.length} keys of the export, largest difference ${worst.toExponential(2)}`);
  // Playing: the clip's time advances by about the wall time (never more;
  // at least a third of it between two readings a second apart, however
  // late the first frames come on a loaded machine), and s is the clock's
  // s at it.
  await page.evaluate(() => window.rollspin.seekTime(0));
  const wallStart = Date.now();
  await page.evaluate(() => window.rollspin.play());
  await page.waitForTimeout(500);
  const first = await page.evaluate(() => window.rollspin.state().time);
  const wallFirst = Date.now();
  await page.waitForTimeout(1000);
  const st = await page.evaluate(() => { window.rollspin.pause(); return { ...window.rollspin.state(), sAt: window.rollspin.sAt(window.rollspin.state().time) }; });
  const wall = (Date.now() - wallStart) / 1000, between = (Date.now() - wallFirst) / 1000;
  check(st.time > 0 && st.time <= wall + 0.1, `${scene}: after ${wall.toFixed(2)} s of play the clip is at ${st.time} s`);
  // Above, the first reading may be stale by a late frame or more on a
  // loaded machine (CI saw 1.15 s of clip in 1.03 s between readings), so
  // the pair gets 0.3 s; the total since play() (checked just above, from
  // before play started) bounds the pace to 0.1 s.
  check(st.time - first >= Math.min(0.3 * between, duration - first - 1e-9) && st.time - first <= between + 0.3,
        `${scene}: in ${between.toFixed(2)} s of play the clip went from ${first} s to ${st.time} s`);
  check(Math.abs(st.s - st.sAt) <= 1e-9 * length, `${scene}: playing shows s = ${st.s}, the clock ${st.sAt} at ${st.time} s`);
  return gltf;
}

// A storyboard on several surfaces shows each chapter's surface (GLB nodes "surface", "surface.1", …).
async function checkSurfaces(page, scene, gltf) {
  const chapters = await page.evaluate(() => window.rollspin.chapters);
  const surfaces = new Set(chapters.map((c) => c.surface));
  for (const k of surfaces)
    check(gltf.nodes.some((n) => n.name === (k === 0 ? 'surface' : `surface.${k}`)), `${scene}: no GLB node for surface ${k}`);
  if (scene === 'torus-to-floor') check(surfaces.size === 2, `${scene}: ${surfaces.size} surfaces in the chapters`);
  for (const c of chapters.filter((x) => x.end > x.start)) {
    const st = await page.evaluate((s) => { window.rollspin.seek(s); return window.rollspin.state(); }, 0.5 * (c.start + c.end));
    check(st.surface === c.surface, `${scene}: in chapter ${c.number} the page shows surface ${st.surface}, not ${c.surface}`);
  }
}

async function checkScene(context, scene, dir) {
  const html = path.join(dir, `${scene}.html`);
  execFileSync(rollspin, ['render', scene, '-o', html, '--quiet'], { stdio: 'pipe' });
  const text = fs.readFileSync(html, 'utf8');
  check(text.length <= MAX_BYTES, `${scene}: the page is ${text.length} bytes, over ${MAX_BYTES}`);
  check(/<meta name="generator" content="rollspin [^"]+">/.test(text), `${scene}: no generator meta`);
  check(/<script type="application\/toml" id="rollspin-scene">[^]*\[ball\]/.test(text), `${scene}: no scene text`);
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
  await page.goto(pathToFileURL(html).href);
  await page.evaluate(() => window.rollspin.ready);
  await checkStates(page, scene, dir);
  await page.evaluate(() => window.rollspin.seek(window.rollspin.length * 0.37));
  await page.waitForTimeout(100);
  await checkPixels(page, scene, dir);
  await checkCheapSurfaces(page, scene);
  await checkKeys(page, scene);
  await checkChapters(page, scene);
  await checkSurfaces(page, scene, await checkClock(page, scene, dir));
  check(errors.length === 0, `${scene}: the page reported errors: ${errors.join('; ')}`);
  await page.close();
}

async function main() {
  fs.mkdirSync(workDir, { recursive: true });
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'rollspin-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: CHROMIUM, headless: true, args: CHROMIUM_ARGS, viewport: { width: 1280, height: 720 },
  });
  // Every request that leaves the file fails the test: the page must work offline.
  const network = [];
  await context.route('**/*', (route) => {
    const url = route.request().url();
    if (/^(file|data|blob):/.test(url)) return route.continue();
    network.push(url);
    return route.abort();
  });
  try {
    for (const scene of SCENES) {
      const start = Date.now();
      await checkScene(context, scene, workDir);
      console.log(`${scene}: checked in ${((Date.now() - start) / 1000).toFixed(1)} s`);
    }
  } finally {
    await context.close();
    fs.rmSync(profile, { recursive: true, force: true });
  }
  check(network.length === 0, `the pages asked the network for: ${network.join(', ')}`);
  for (const f of failures) console.error(`FAIL ${f}`);
  console.log(failures.length ? `${failures.length} failures` : 'all checks passed');
  process.exit(failures.length ? 1 : 0);
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});
