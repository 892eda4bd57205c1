// The shown robot's motion: samples (sphere centres, neuron outputs, sensor
// values) at increasing simulated times, and a playhead over them that the
// timeline moves. Playing, the playhead advances at `speed` times real time. A
// live stream arrives faster than real time (evolve sends a trajectory in a
// burst) or slower (a quiet bus): the playhead waits at the newest sample until
// more come or the stream is over. At the end of a finished trajectory it holds
// for a moment and starts again when `loop` is on, else it stops (paused).
export const SPEEDS = [0.25, 0.5, 1, 2, 4];

export class Playback {
  constructor() {
    this.playing = true;      // the playhead advances
    this.speed = 1;           // times real time
    this.loop = true;         // start again at the end
    this.clear(null);
  }

  clear(robot) {
    this.robot = robot;
    this.samples = [];
    this.done = false;
    this.simTime = null;      // the playhead (s of simulated time)
    this.index = 0;           // samples[index].time <= simTime
    this.holdUntil = 0;       // ms: hold the last pose until then, then start again
    this.firstDrawn = false;
    this.firstLatencyMs = null;
  }

  add(sample) {
    const n = this.samples.length;
    if (n > 0 && !(sample.time > this.samples[n - 1].time)) return;  // out of order: skip
    this.samples.push(sample);
  }

  finish() { this.done = true; }

  /// Simulated times of the first and last samples (s); null when there are none.
  start() { return this.samples.length ? this.samples[0].time : null; }
  end() { return this.samples.length ? this.samples[this.samples.length - 1].time : null; }

  /// Moves the playhead to simulated time t (s), clamped to the samples.
  seek(t) {
    const s = this.samples;
    if (s.length === 0 || !isFinite(t)) return;
    this.simTime = Math.min(Math.max(t, s[0].time), s[s.length - 1].time);
    this.holdUntil = 0;
    this.locate();
  }

  /// Moves the playhead to the sample `by` samples away from the one shown.
  step(by) {
    const s = this.samples;
    if (s.length === 0) return;
    if (this.simTime === null) this.simTime = s[0].time;
    this.locate();
    // Between two samples, a step back goes to the earlier one.
    const from = by < 0 && s[this.index].time < this.simTime ? this.index + 1 : this.index;
    const i = Math.min(Math.max(from + by, 0), s.length - 1);
    this.simTime = s[i].time;
    this.index = i;
    this.holdUntil = 0;
  }

  /// index: the last sample at or before the playhead (binary search).
  locate() {
    const s = this.samples;
    let lo = 0, hi = s.length - 1;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (s[mid].time <= this.simTime) lo = mid; else hi = mid - 1;
    }
    this.index = lo;
  }

  /// The pose at the playhead: draw a + (b - a) * f; null when there is nothing to draw.
  pose() {
    const s = this.samples;
    if (s.length === 0 || this.simTime === null) return null;
    const a = s[this.index];
    const b = s[Math.min(this.index + 1, s.length - 1)];
    const f = b.time > a.time ? Math.min(1, Math.max(0, (this.simTime - a.time) / (b.time - a.time))) : 0;
    return { a, b, f };
  }

  /// Advances the playhead by dtMs of wall time (when playing); returns pose().
  advance(dtMs, nowMs) {
    const s = this.samples;
    if (s.length === 0) return null;
    if (this.simTime === null) this.simTime = s[0].time;
    const last = s[s.length - 1].time;
    if (this.playing) {
      if (this.simTime >= last && this.done) {
        if (!this.loop) {
          this.playing = false;
        } else {
          if (this.holdUntil === 0) this.holdUntil = nowMs + 1500;
          if (nowMs >= this.holdUntil) {
            this.simTime = s[0].time;
            this.index = 0;
            this.holdUntil = 0;
          }
        }
      } else {
        this.simTime = Math.min(Math.max(this.simTime + this.speed * dtMs / 1000, s[0].time), last);
      }
    }
    while (this.index + 1 < s.length && s[this.index + 1].time <= this.simTime) this.index++;
    const d = this.pose();
    if (!this.firstDrawn) {
      this.firstDrawn = true;
      if (d.a.utime) this.firstLatencyMs = Date.now() - d.a.utime / 1000;
    }
    return d;
  }
}
