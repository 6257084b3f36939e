// Chromium plays a rollspin WebM with its captions: headless Debian Chromium
// (driven by playwright-core from web/node_modules) loads DIR/clip.webm in a
// <video> with DIR/clip.vtt as its <track>, served over HTTP from here, plays
// it, and reads the cues through the TextTrack API; they must be the scene's
// title and captions at the scene's times (see subtitles_browser_test.sh).
//   node subtitles_browser.mjs NODE_MODULES DIR SCENE.toml
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const [nodeModules, dir, scenePath] = process.argv.slice(2);
const { chromium } = await import(pathToFileURL(path.join(nodeModules, 'playwright-core', 'index.mjs')).href);

// The scene's title and captions, read from its file (one per line, in order).
const sceneText = fs.readFileSync(scenePath, 'utf8');
const title = /^title = "(.*)"/m.exec(sceneText)[1];
const captions = [...sceneText.matchAll(/^caption = "(.*)"/gm)].map((m) => m[1]);
// storyboard.toml at 2 fps (as subtitles_cli_test.cpp derives it): the
// captions change at frames 7, 21, 26 and the clip ends at frame 31.
const bounds = [0, 3.5, 10.5, 13.0, 15.5];
const expected = captions.map((c, k) => ({ start: bounds[k], end: bounds[k + 1], text: `${title}\n${c}` }));

const types = { '.html': 'text/html', '.webm': 'video/webm', '.vtt': 'text/vtt; charset=utf-8' };
const page = `<!doctype html><meta charset="utf-8"><video id="v" src="clip.webm" muted preload="auto">
<track id="t" kind="subtitles" srclang="en" label="Captions" src="clip.vtt" default></video>`;
// Byte ranges as a media element asks for them.
const server = http.createServer((req, res) => {
  const name = path.basename(new URL(req.url, 'http://localhost').pathname) || 'index.html';
  if (name === 'index.html') return res.writeHead(200, { 'Content-Type': types['.html'] }).end(page);
  const file = path.join(dir, name);
  if (!fs.existsSync(file)) return res.writeHead(404).end();
  const size = fs.statSync(file).size;
  const range = /bytes=(\d*)-(\d*)/.exec(req.headers.range || '');
  const headers = { 'Content-Type': types[path.extname(name)] || 'application/octet-stream', 'Accept-Ranges': 'bytes' };
  if (!range) return res.writeHead(200, { ...headers, 'Content-Length': size }).end(fs.readFileSync(file));
  const first = range[1] ? Number(range[1]) : 0, last = range[2] ? Number(range[2]) : size - 1;
  res.writeHead(206, { ...headers, 'Content-Range': `bytes ${first}-${last}/${size}`, 'Content-Length': last - first + 1 });
  fs.createReadStream(file, { start: first, end: last }).pipe(res);
});
await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));

const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'rollspin-chromium-'));
let failures = 0;
const context = await chromium.launchPersistentContext(profile, {
  executablePath: '/usr/bin/chromium',
  headless: true,
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
         '--disable-background-networking', '--disable-component-update', '--disable-sync'],
});
try {
  const tab = await context.newPage();
  await tab.goto(`http://127.0.0.1:${server.address().port}/index.html`);
  const seen = await tab.evaluate(async () => {
    const video = document.getElementById('v'), track = document.getElementById('t');
    const within = (promise, ms, what) =>
      Promise.race([promise, new Promise((_, reject) => setTimeout(() => reject(new Error(`${what}: timed out`)), ms))]);
    const event = (target, name) => new Promise((resolve, reject) => {
      target.addEventListener(name, resolve, { once: true });
      target.addEventListener('error', () => reject(new Error(`${name}: error ${video.error?.message ?? ''}`)), { once: true });
    });
    track.track.mode = 'hidden';  // load the cues without drawing them
    if (track.readyState !== 2) await within(event(track, 'load'), 20000, 'the track');
    if (video.readyState < 2) await within(event(video, 'loadeddata'), 20000, 'the video');
    await video.play();
    await within(new Promise((resolve) => {
      const tick = () => (video.currentTime > 0.3 ? resolve() : requestAnimationFrame(tick));
      tick();
    }), 20000, 'playing');
    video.pause();
    const cues = Array.from(track.track.cues, (c) => ({ start: c.startTime, end: c.endTime, text: c.text }));
    return { cues, duration: video.duration, width: video.videoWidth, error: video.error?.message ?? null,
             tracks: video.textTracks.length };
  });
  console.log(`chromium: ${seen.width}-px-wide video of ${seen.duration} s played; ${seen.tracks} text track(s); ` +
              `${seen.cues.length} cue(s)`);
  const check = (ok, what) => { if (!ok) { console.log(`FAILED: ${what}`); failures++; } };
  check(seen.error === null, `video error ${seen.error}`);
  check(Math.abs(seen.duration - 15.5) < 0.1, `duration ${seen.duration}, expected 15.5 s`);
  check(seen.cues.length === expected.length, `${seen.cues.length} cues, expected ${expected.length}`);
  expected.forEach((e, k) => {
    const c = seen.cues[k] || {};
    check(Math.abs(c.start - e.start) < 0.0015 && Math.abs(c.end - e.end) < 0.0015,
          `cue ${k} at ${c.start}–${c.end} s, expected ${e.start}–${e.end} s`);
    check(c.text === e.text, `cue ${k} says ${JSON.stringify(c.text)}, expected ${JSON.stringify(e.text)}`);
  });
} finally {
  await context.close();
  server.close();
  fs.rmSync(profile, { recursive: true, force: true });
}
console.log(failures === 0 ? 'ok: Chromium read the scene\'s captions at its times' : `${failures} failure(s)`);
process.exit(failures === 0 ? 0 : 1);
