// Playback over arc length: the current s, play/pause at a speed, and the
// page's controls (scrubber, buttons, chapters, readouts, keyboard). It
// owns no 3-D state: it calls `onChange(s)` and the page redraws.
import { angles } from './timeline.js';

const DEG = 180 / Math.PI;
// Arrow keys move s by this share of the path (Shift: ten times as far).
const KEY_STEP = 1 / 200;

export class Player {
  // clock: the clip's (ClipClock): at 1× the page plays as the MP4 does, holds included.
  constructor(timeline, clock, onChange) {
    this.timeline = timeline;
    this.clock = clock;
    this.speed = 1;
    this.s = 0;
    this.t = 0;  // the clip's second shown
    this.playing = false;
    this.loop = false;  // at the end: start again (else stop)
    this.onChange = onChange;
    this.listeners = [];
  }

  // Moves to s (the scrubber, keys, chapters); the clock follows.
  seek(s) {
    this.s = this.timeline.clamp(s);
    this.t = this.clock.timeAt(this.s);
    this.onChange(this.s);
    return this.s;
  }

  // Moves to the clip's second t; s follows.
  seekTime(t) {
    this.t = Math.min(this.clock.duration, Math.max(0, Number(t)));
    this.s = this.timeline.clamp(this.clock.sAt(this.t));
    this.onChange(this.s);
    return this.t;
  }

  play() {
    if (this.t >= this.clock.duration || this.s >= this.timeline.length) this.seekTime(0);
    this.playing = true;
    this.last = null;
    this.notify();
  }

  pause() {
    this.playing = false;
    this.notify();
  }

  toggle() {
    if (this.playing) this.pause();
    else this.play();
  }

  // Advances the clip's clock by the time since the last call (requestAnimationFrame's clock, ms).
  tick(now) {
    if (!this.playing) return false;
    if (this.last !== null) {
      const t = this.t + ((now - this.last) / 1000) * this.speed;
      const end = this.clock.duration;
      this.seekTime(t < end ? t : this.loop ? t % end : end);
      if (t >= end && !this.loop) {
        this.pause();
        return true;
      }
    }
    this.last = now;
    return true;
  }

  notify() {
    for (const f of this.listeners) f(this);
  }
}

// Sets an element's text only when it changes: each change costs the page a
// layout and a repaint, which on a software renderer cost as much as a frame.
const shownText = new Map();
function text(id, value) {
  if (shownText.get(id) === value) return;
  shownText.set(id, value);
  document.getElementById(id).textContent = value;
}

// The readouts the renders print, live; the caption of the current chapter.
export function showReadouts(timeline, s) {
  const a = angles(timeline.quaternion(s));
  text('arc', `s = ${s.toFixed(2)} of ${timeline.length.toFixed(2)}`);
  text('rotation', `lab rotation angle = ${(a.rotation * DEG).toFixed(1)}°`);
  text('spinor', `spinor angle ψ = ${(a.spinor * DEG).toFixed(1)}°`);
  text('sheet', a.negativeSheet ? 'spinor sheet: negative (U ≈ −1)' : 'spinor sheet: positive (U ≈ +1)');
  document.getElementById('sheet').classList.toggle('negative', a.negativeSheet);
}

// One button per storyboard segment; the current one marked.
function buildChapters(player, timeline) {
  const nav = document.getElementById('chapters');
  const buttons = timeline.chapters.map((chapter) => {
    const b = document.createElement('button');
    b.type = 'button';
    b.textContent = `${chapter.number}. ${chapter.caption || chapter.title || 'segment ' + chapter.number}`;
    b.setAttribute('aria-label', `Chapter ${chapter.number}: ${b.textContent}, from s = ${chapter.start.toFixed(2)}`);
    b.dataset.start = String(chapter.start);
    b.addEventListener('click', () => player.seek(chapter.start));
    nav.append(b);
    return b;
  });
  let shown = null;
  // The chapter of the clip's second t (a hold shows its own caption while
  // s rests where the motion before it ended); by s where the clock has none.
  return (s, t) => {
    const atTime = player.clock?.segmentAt(t);
    const current = atTime === null || atTime === undefined ? timeline.segment(s) : atTime + 1;
    if (current === shown) return;
    shown = current;
    buttons.forEach((b, k) => {
      const on = timeline.chapters[k].number === current;
      b.classList.toggle('current', on);
      if (on) b.setAttribute('aria-current', 'step');
      else b.removeAttribute('aria-current');
    });
    const chapter = timeline.chapters.find((c) => c.number === current);
    text('caption', chapter ? chapter.caption : '');
  };
}

// Keys: space play/pause, ←/→ scrub (Shift: farther), Home/End, PageUp/PageDown
// chapters; ↑/↓ and Alt+←/→ orbit the focused view, +/− zoom, R reset, F fullscreen.
function onKey(event, player, timeline, actions) {
  if (event.target.tagName === 'SELECT') return;
  // A focused button takes space and Enter itself (a click).
  if (event.target.tagName === 'BUTTON' && (event.key === ' ' || event.key === 'Enter')) return;
  const step = timeline.length * KEY_STEP * (event.shiftKey ? 10 : 1);
  const chapterStarts = timeline.chapters.map((c) => c.start);
  const handled = {
    ' ': () => player.toggle(),
    ArrowRight: () => (event.altKey ? actions.orbit(0.1, 0) : player.seek(player.s + step)),
    ArrowLeft: () => (event.altKey ? actions.orbit(-0.1, 0) : player.seek(player.s - step)),
    ArrowUp: () => actions.orbit(0, 0.1),
    ArrowDown: () => actions.orbit(0, -0.1),
    Home: () => player.seek(0),
    End: () => player.seek(timeline.length),
    PageDown: () => player.seek(chapterStarts.find((c) => c > player.s + 1e-9) ?? timeline.length),
    PageUp: () => player.seek([...chapterStarts].reverse().find((c) => c < player.s - 1e-9) ?? 0),
    '+': () => actions.zoom(0.85),
    '=': () => actions.zoom(0.85),
    '-': () => actions.zoom(1 / 0.85),
    r: () => actions.reset(),
    f: () => actions.fullscreen(),
  }[event.key];
  if (!handled) return;
  event.preventDefault();
  handled();
}

export function bindControls(player, timeline, actions) {
  const scrubber = document.getElementById('scrubber');
  scrubber.max = String(timeline.length);
  scrubber.step = String(timeline.length / 2000);
  scrubber.addEventListener('input', () => player.seek(Number(scrubber.value)));
  // The range input would take arrows and Home/End itself: the page's keys do it the same everywhere.
  scrubber.addEventListener('keydown', (e) => e.preventDefault());
  const playButton = document.getElementById('play');
  playButton.addEventListener('click', () => player.toggle());
  document.getElementById('speed').addEventListener('change', (e) => (player.speed = Number(e.target.value)));
  document.getElementById('reset').addEventListener('click', actions.reset);
  document.getElementById('fullscreen').addEventListener('click', actions.fullscreen);
  document.addEventListener('keydown', (e) => onKey(e, player, timeline, actions));
  player.listeners.push((p) => {
    playButton.textContent = p.playing ? 'Pause' : 'Play';
    playButton.setAttribute('aria-pressed', String(p.playing));
    playButton.setAttribute('aria-label', p.playing ? 'Pause' : 'Play');
  });
  const showChapter = buildChapters(player, timeline);
  return (s) => {
    scrubber.value = String(s);
    scrubber.setAttribute('aria-valuetext', `s = ${s.toFixed(2)} of ${timeline.length.toFixed(2)}`);
    showReadouts(timeline, s);
    showChapter(s, player.t);
  };
}
