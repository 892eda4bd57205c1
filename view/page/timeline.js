// The timeline under the 3D view: play/pause, one sample back or forward, a
// seek bar over the shown trajectory with its simulated time, the playback
// speed, loop, a slider over the run's champions, and whether the page follows
// the live run ("back to live" returns to it). Keys: space plays or pauses,
// left/right arrows step one sample. Every control is the user taking over:
// the page stops following the newest champion until "back to live".
import { SPEEDS } from "/playback.js";

const num = (v, d = 2) => (typeof v === "number" && isFinite(v) ? v.toFixed(d) : "–");

export class Timeline {
  /// playback: the Playback the controls move; on: {take() (the user took the
  /// controls), live() (back to live), champion(id) (show that champion)}.
  constructor(playback, on) {
    this.playback = playback;
    this.on = on;
    this.champions = [];
    const $ = (id) => document.getElementById(id);
    this.el = { play: $("tl-play"), back: $("tl-back"), fwd: $("tl-fwd"), seek: $("tl-seek"), time: $("tl-time"),
                speed: $("tl-speed"), loop: $("tl-loop"), gen: $("tl-gen"), genLabel: $("tl-gen-label"),
                state: $("tl-state"), live: $("tl-live") };
    const e = this.el;
    e.speed.replaceChildren(...SPEEDS.map((s) => {
      const o = document.createElement("option");
      o.value = String(s); o.textContent = `${s}×`; o.selected = s === playback.speed;
      return o;
    }));
    const button = (b, f) => b.addEventListener("click", () => { f(); b.blur(); });
    button(e.play, () => this.toggle());
    button(e.back, () => this.step(-1));
    button(e.fwd, () => this.step(1));
    button(e.live, () => this.on.live());
    e.seek.addEventListener("input", () => this.seek(Number(e.seek.value)));
    e.speed.addEventListener("change", () => { this.playback.speed = Number(e.speed.value); });
    e.loop.addEventListener("change", () => { this.playback.loop = e.loop.checked; });
    e.gen.addEventListener("input", () => this.showGenLabel(Number(e.gen.value)));
    e.gen.addEventListener("change", () => {
      const c = this.champions[Number(e.gen.value)];
      if (c) { this.on.take(); this.on.champion(c.id); }
    });
    window.addEventListener("keydown", (k) => {
      if (k.target.closest && k.target.closest("input, select, textarea")) return;
      if (k.key === " ") {
        if (k.target.closest && k.target.closest("button")) return;  // the focused button's own click
        k.preventDefault(); this.toggle();
      }
      else if (k.key === "ArrowLeft") { k.preventDefault(); this.step(-1); }
      else if (k.key === "ArrowRight") { k.preventDefault(); this.step(1); }
    });
  }

  play() {
    const p = this.playback;
    if (p.done && p.simTime !== null && p.simTime >= p.end()) p.seek(p.start());  // at the end: from the start
    p.playing = true;
  }
  pause() { this.on.take(); this.playback.playing = false; }
  toggle() { this.on.take(); if (this.playback.playing) this.pause(); else this.play(); }
  step(by) { this.on.take(); this.playback.playing = false; this.playback.step(by); }
  seek(t) { this.on.take(); this.playback.seek(t); }

  setChampions(list) {
    this.champions = list;
    const e = this.el;
    e.gen.max = String(Math.max(0, list.length - 1));
    e.gen.disabled = list.length < 2;
  }

  showGenLabel(i) {
    const c = this.champions[i];
    this.el.genLabel.textContent = c ? `gen ${c.gen} · #${c.id}` : "–";
    this.el.genLabel.title = c ? `champion of generation ${c.gen}: genome ${c.id}` : "";
  }

  /// Brings the controls up to date (every frame: cheap when nothing changed).
  /// following: the page shows the newest champion as it comes; source: the
  /// hello frame's mode, "live" (a live run), "log" or "file" (one champion
  /// saved as a file, or a trial's robot: nothing to follow).
  update(following, source) {
    const live = source !== "log" && source !== "file";
    const p = this.playback, e = this.el;
    const t0 = p.start(), t1 = p.end();
    const playing = p.playing;
    if (e.play.dataset.playing !== String(playing)) {
      e.play.dataset.playing = String(playing);
      e.play.textContent = playing ? "❚❚" : "▶";
      e.play.title = (playing ? "pause" : "play") + " (space)";
    }
    if (t0 !== null) {
      if (e.seek.min !== String(t0)) e.seek.min = String(t0);
      if (e.seek.max !== String(t1)) e.seek.max = String(t1);
      if (document.activeElement !== e.seek && p.simTime !== null) e.seek.value = String(p.simTime);
    }
    e.seek.disabled = t0 === null;
    const time = `${num(p.simTime)} / ${num(t1)} s`;
    if (e.time.textContent !== time) e.time.textContent = time;
    const id = p.robot ? p.robot.id : null;
    const i = this.champions.findIndex((c) => c.id === id);
    if (i >= 0 && document.activeElement !== e.gen && e.gen.value !== String(i)) { e.gen.value = String(i); }
    if (document.activeElement !== e.gen) this.showGenLabel(i >= 0 ? i : -1);
    const where = live ? "live" : source === "file" ? "the file" : "the log";
    const file = source === "file";
    // The text's length never moves the panels: the bar is one line of fixed height.
    const state = following && file ? (p.robot ? `genome ${id}: ${playing ? "playing" : "paused"}` : "waiting for the champion") :
                  following ? `following ${where}` :
                  !p.robot ? "waiting for the champion asked for" :
                  t0 === null ? `waiting for the samples of genome ${id}` :
                  playing ? `playing genome ${id} (not following ${where})` : `paused at ${num(p.simTime)} s of genome ${id}`;
    if (e.state.textContent !== state) {
      e.state.textContent = state;
      e.state.className = following ? "following" : "held";
    }
    e.live.hidden = following || file;
    e.live.textContent = `back to ${where}`;
  }
}
