// The shown robot's motion: samples (sphere centres, neuron outputs, sensor
// values) at increasing simulated times, played at real time. A live stream
// arrives faster than real time (evolve sends a trajectory in a burst) or
// slower (a quiet bus): the play clock waits at the newest sample until more
// come or the stream is over; a finished trajectory holds for a moment and
// plays again.
export class Playback {
  constructor() { this.clear(null); }

  clear(robot) {
    this.robot = robot;
    this.samples = [];
    this.done = false;
    this.simTime = null;      // play clock (s of simulated time)
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

  /// Advances the clock by dtMs of wall time; returns {a, b, f}: draw
  /// a + (b - a) * f, or null when there is nothing to draw.
  advance(dtMs, nowMs) {
    const s = this.samples;
    if (s.length === 0) return null;
    if (this.simTime === null) this.simTime = s[0].time;
    const last = s[s.length - 1].time;
    if (this.simTime >= last && this.done) {
      if (this.holdUntil === 0) this.holdUntil = nowMs + 1500;
      if (nowMs >= this.holdUntil) {
        this.simTime = s[0].time;
        this.index = 0;
        this.holdUntil = 0;
      }
    } else {
      this.simTime = Math.min(this.simTime + dtMs / 1000, last);
    }
    while (this.index + 1 < s.length && s[this.index + 1].time <= this.simTime) this.index++;
    const a = s[this.index];
    const b = s[Math.min(this.index + 1, s.length - 1)];
    const f = b.time > a.time ? Math.min(1, Math.max(0, (this.simTime - a.time) / (b.time - a.time))) : 0;
    if (!this.firstDrawn) {
      this.firstDrawn = true;
      if (a.utime) this.firstLatencyMs = Date.now() - a.utime / 1000;
    }
    return { a, b, f };
  }
}
