// The page's entry point (bundled by esbuild into the one HTML file): reads
// the embedded timeline and GLB, builds the views and the controls, and
// publishes the JavaScript API that tests and embedding pages use:
//   window.rollspin.ready        a Promise, resolved once the first frame is drawn
//   window.rollspin.length       the path's arc length
//   window.rollspin.seek(s)      moves to s (clamped to [0, length]); returns s
//   window.rollspin.state()      {s, quaternion: [qw, qx, qy, qz], bloch: [x, y, z], segment, surface, time}
//   window.rollspin.duration     the clip's length in seconds (the MP4's, holds included)
//   window.rollspin.sAt(t), timeAt(s), seekTime(t)   the clip's clock (playback at 1× follows it)
//   window.rollspin.play(), pause(), chapters, measureFps(seconds) → Promise<frames per second>,
//   views() → [{name: "ball" | "bloch", element, centre: [x, y]}] (page pixels)
//   renderScale()  the share of the device pixel ratio the views render at (FramePacer: below 1 only while playing)
//   drawNow()      draws both views in this task, for a caller that reads the canvases right after
//   adaptiveResolution   true (the default): playback lowers renderScale to hold 30 frames/s; false: full resolution
//   cheapSurfaces  true (the default): closed surfaces culled, shadow lookups only near the ball (surface_cost.js);
//                  false: every surface triangle drawn both sides with the lookups (the same picture, slower)
import { Timeline } from './timeline.js';
import { TwinScene, embeddedBytes } from './twin_scene.js';
import { Player, bindControls } from './player.js';
import { ClipClock } from './clip_clock.js';
import { FramePacer } from './frame_pacer.js';

function readJson(id) {
  return JSON.parse(document.getElementById(id).textContent);
}

function fullscreen() {
  if (document.fullscreenElement) document.exitFullscreen();
  else document.documentElement.requestFullscreen?.();
}

// Counts the frames drawn while playing over `seconds` (requestAnimationFrame's clock).
function measureFps(player, counter, seconds) {
  return new Promise((resolve) => {
    const wasPlaying = player.playing, looping = player.loop;
    player.loop = true;  // a short path must not stop the count
    player.play();
    const start = performance.now(), frames = counter.frames;
    setTimeout(() => {
      const fps = (counter.frames - frames) / ((performance.now() - start) / 1000);
      player.loop = looping;
      if (!wasPlaying) player.pause();
      resolve(fps);
    }, seconds * 1000);
  });
}

function start() {
  const data = readJson('rollspin-timeline');
  const timeline = new Timeline(data);
  const twin = new TwinScene(document.getElementById('ball-view'), document.getElementById('bloch-view'), data.viewDeg);
  let dirty = true;
  const clock = new ClipClock(data.clock);
  const player = new Player(timeline, clock, () => (dirty = true));
  const focusedView = () => (document.activeElement?.id === 'bloch-view' ? twin.blochView : twin.ballView);
  const actions = {
    orbit: (azimuth, elevation) => { focusedView().orbit(azimuth, elevation); dirty = true; },
    zoom: (factor) => { focusedView().zoom(factor); dirty = true; },
    reset: () => { for (const v of twin.views) v.reset(); dirty = true; },
    fullscreen,
  };
  const showControls = bindControls(player, timeline, actions);
  for (const v of twin.views) v.controls.addEventListener('change', () => (dirty = true));
  const counter = { frames: 0 };
  const api = {
    length: timeline.length,
    chapters: timeline.chapters,
    seek: (s) => player.seek(s),
    state: () => ({ ...timeline.state(player.s), time: player.t }),
    duration: clock.duration,
    sAt: (t) => clock.sAt(t),
    timeAt: (s) => clock.timeAt(s),
    seekTime: (t) => player.seekTime(t),
    play: () => player.play(),
    pause: () => player.pause(),
    measureFps: (seconds = 5) => measureFps(player, counter, seconds),
    views: () => twin.screenCentres(),
    renderScale: () => twin.renderScale,
    // Draws both views now: their canvases hold the frame until this task
    // ends (the page does not preserve drawing buffers: cheaper to present),
    // so a caller reads them (drawImage, toDataURL) right after.
    drawNow: () => { twin.pose(timeline, player.s); twin.render(); },
  };
  window.rollspin = api;
  api.ready = twin.load(embeddedBytes(document.getElementById('rollspin-glb'))).then(() => {
    new ResizeObserver(() => { twin.resize(); dirty = true; }).observe(document.getElementById('stage'));
    twin.resize();
    const pacer = new FramePacer(twin);
    Object.defineProperty(api, 'adaptiveResolution', {
      get: () => pacer.enabled, set: (on) => (pacer.enabled = Boolean(on)), enumerable: true });
    Object.defineProperty(api, 'cheapSurfaces', {
      get: () => twin.cheapSurfaces, set: (on) => { twin.cheapSurfaces = on; dirty = true; }, enumerable: true });
    const frame = (now) => {
      if (player.tick(now)) dirty = true;
      if (dirty) {
        twin.pose(timeline, player.s);
        twin.render();
        showControls(player.s);
        counter.frames += 1;
        dirty = false;
      }
      if (pacer.drawn(now, player.playing)) dirty = true;
      requestAnimationFrame(frame);
    };
    twin.pose(timeline, 0);
    twin.render();
    showControls(0);
    requestAnimationFrame(frame);
  });
}

start();
