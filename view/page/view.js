// robozoo-view's page: one WebSocket to the server (frames described in
// view/state/frames.hpp), the 3D view, the chart, the strip, the run's facts and its
// champions, the shown champion's CPPN and the timeline. It opens on the
// newest champion and plays it: no mouse needed.
import { Scene } from "/scene.js";
import { Chart } from "/chart.js";
import { Strip } from "/strip.js";
import { Playback } from "/playback.js";
import { Timeline } from "/timeline.js";
import { CppnView } from "/cppn.js";
import { offlineFrames, setupSave } from "/offline.js";

const $ = (id) => document.getElementById(id);
const scene = new Scene($("stage"));
const chart = new Chart($("chart"));
const strip = new Strip({ canvas: $("strip"), key: $("strip-key"), groups: $("strip-groups"),
                          scroll: $("strip-scroll"), spacer: $("strip-spacer") });
const cppn = new CppnView($("cppn"), $("cppn-key"));
const playback = new Playback();

const state = {
  hello: null, run: null, last: null, champions: [], stats: null,
  following: true,      // show the newest champion as it arrives (false once the user takes the controls)
  liveRobot: null,      // the newest live robot and its samples, kept while the user looks elsewhere
  liveSamples: [], liveDone: false,
  moment: null,         // {run, genome, t} named by the URL, until the page lands there
  hash: "",             // the URL's moment as last written
  frames: 0, stripDrawn: 0, fps: 0, fpsFrames: 0, fpsSince: performance.now(), framesReceived: 0,
};

const timeline = new Timeline(playback, {
  take: () => { state.following = false; state.moment = null; },
  live: () => backToLive(),
  champion: (id) => replay(id),
});

const num = (v, d = 2) => (typeof v === "number" && isFinite(v) ? v.toFixed(d) : "–");

function showRobot(robot) {
  playback.clear(robot);
  scene.setRobot(robot.radius, robot.leaf, robot.start);
  strip.setRobot(robot);
  cppn.setRobot(robot);
  chart.setCursor(robot.gen);
  const r = robot.replay ? " (replay" + (robot.resimulated ? ", re-simulated" : "") + ")" : "";
  $("robot-caption").textContent = `genome ${robot.id}, generation ${robot.gen}, fitness ${num(robot.fitness)}${r}`;
  markShown();
}

function sampleOf(p) { return { time: p.time, step: p.step, c: p.c, n: p.n, s: p.s, utime: p.utime || 0 }; }

function facts() {
  const r = state.run, g = state.last, st = state.stats, rows = [];
  if (state.hello) rows.push(["source", `${state.hello.mode}: ${state.hello.source}`]);
  if (r) {
    rows.push(["run", r.id], ["regime", r.regime], ["seed", r.seed], ["version", r.version],
              ["target", r.target.map((v) => num(v, 1)).join(", ") + " m"]);
  }
  if (g) {
    const prev = chart.gens.length > 1 ? chart.gens[chart.gens.length - 2] : null;
    const evals = prev ? g.evaluations - prev.evaluations : g.evaluations;
    const pop = r ? r.population : 0;
    rows.push(["generation", `${g.g + 1} of ${r ? r.generations : "?"}`],
              ["best / mean", `${num(g.best)} / ${num(g.mean)}`], ["best so far", num(g.bsf)],
              ["species", g.species], ["eval/s", g.gen_s > 0 ? num(evals / g.gen_s, 1) : "–"]);
    const o = g.outcomes, share = (k) => (pop > 0 ? num(100 * o[k] / pop, 0) + " %" : o[k]);
    rows.push(["not simulated", share("not_simulated")], ["completed", share("completed")],
              ["stopped early", share("stopped_early")], ["acceleration fault", share("accel_fault")],
              ["rolling", `${share("rolling_contact")} contact, ${share("rolling_spin")} spin`]);
  }
  if (st) rows.push(["dropped poses", `${st.dropped} here (${st.dropped_all} all pages)`],
                    ["bad messages", `${st.bad} of ${st.messages}`], ["pages", st.pages]);
  rows.push(["frame rate", num(state.fps, 0) + " fps"]);
  const dl = $("facts");
  dl.replaceChildren(...rows.flatMap(([k, v]) => {
    const dt = document.createElement("dt"), dd = document.createElement("dd");
    dt.textContent = k; dd.textContent = String(v);
    return [dt, dd];
  }));
}

function addChampion(c) {
  state.champions.push(c);
  const li = document.createElement("li");
  li.dataset.id = c.id;
  const b = document.createElement("button");
  b.type = "button";
  b.textContent = `gen ${c.gen} · genome ${c.id} · ${num(c.fitness)}`;
  b.addEventListener("click", () => { timeline.on.take(); replay(c.id); });
  li.appendChild(b);
  $("champions").prepend(li);
  timeline.setChampions(state.champions);
  if (state.moment && state.moment.genome === c.id) land();
  markShown();
}

function markShown() {
  const id = playback.robot ? playback.robot.id : null;
  for (const li of $("champions").children) li.classList.toggle("shown", Number(li.dataset.id) === id);
}

// Requests to the server go through `send` (the socket; an offline page may set another).
let socket = null;
let send = (obj) => { if (socket && socket.readyState === WebSocket.OPEN) socket.send(JSON.stringify(obj)); };
function replay(id) { send({ t: "replay", id }); }

function backToLive() {
  state.following = true;
  state.moment = null;
  playback.playing = true;
  if (state.liveRobot) {
    showRobot(state.liveRobot);
    for (const s of state.liveSamples) playback.add(s);
    if (state.liveDone) playback.finish();
  }
}

function resetRun() {
  state.run = null; state.last = null; state.champions = [];
  state.liveRobot = null; state.liveSamples = []; state.liveDone = false; state.following = state.moment === null;
  if (state.moment) state.moment.asked = false;  // a new connection: ask again
  $("champions").replaceChildren();
  timeline.setChampions(state.champions);
  chart.clear();
}

// The moment named by the URL (#run=ID&genome=N&t=S): the page asks for a
// replay of that champion, then stops at that time once its samples reach it.
function parseMoment(hash) {
  const q = new URLSearchParams(hash.replace(/^#/, ""));
  if (!q.has("genome")) return null;
  const genome = Number(q.get("genome")), t = Number(q.get("t") || "0");
  if (!Number.isInteger(genome) || !isFinite(t)) return null;
  return { run: q.get("run"), genome, t };
}

/// Moves towards the URL's moment: asks for its champion, or seeks to its time.
function land() {
  const m = state.moment;
  if (!m) return;
  if (m.run && state.run && state.run.id !== m.run) return;  // another run: nothing to land on
  // Only the replay asked for lands: a live stream of the same genome may come first.
  if (!playback.robot || playback.robot.id !== m.genome || !playback.robot.replay) {
    if (!m.asked && state.champions.some((c) => c.id === m.genome)) { m.asked = true; replay(m.genome); }
    return;
  }
  const end = playback.end();
  if (end === null || (end < m.t && !playback.done)) return;  // its samples have not reached t yet
  playback.playing = false;
  playback.seek(m.t);
  state.moment = null;
}

function writeMoment() {
  if (state.moment) return;  // not there yet: the URL keeps the moment asked for
  let hash = "";
  if (!state.following && playback.robot && playback.simTime !== null)
    hash = `#run=${encodeURIComponent(state.run ? state.run.id : "")}&genome=${playback.robot.id}&t=${playback.simTime.toFixed(2)}`;
  if (hash !== state.hash) {
    state.hash = hash;
    history.replaceState(null, "", hash || location.pathname + location.search);
  }
}

/// Every frame from the server (view/state/frames.hpp) comes in here, whatever its
/// source: the socket below, or recorded frames fed by robozooView.feed.
function onFrame(m) {
  state.framesReceived++;
  switch (m.t) {
    case "hello": state.hello = m; resetRun(); $("source").textContent = `${m.mode} · ${m.source}`; break;
    case "run": resetRun(); state.run = m; scene.setTarget(m.target); break;
    case "history": for (const g of m.gens) chart.add(g); state.last = m.gens.length ? m.gens[m.gens.length - 1] : state.last; break;
    case "gen": chart.add(m); state.last = m; break;
    case "champions": for (const c of m.list) addChampion(c); break;
    case "champion": addChampion(m); break;
    case "robot":
      if (m.replay) {
        state.following = false; showRobot(m);
        if (!state.moment) playback.playing = true;
        break;
      }
      state.liveRobot = m; state.liveSamples = []; state.liveDone = false;
      if (state.following) showRobot(m);
      break;
    case "pose": {
      const s = sampleOf(m);
      if (state.liveRobot && m.id === state.liveRobot.id) state.liveSamples.push(s);
      if (playback.robot && m.id === playback.robot.id) { playback.add(s); land(); }
      break;
    }
    case "poses": {
      const list = m.list.map(sampleOf);
      const live = state.liveRobot && m.id === state.liveRobot.id && !(playback.robot && playback.robot.replay);
      if (live) { state.liveSamples.push(...list); if (m.done) state.liveDone = true; }
      if (playback.robot && m.id === playback.robot.id) {
        if (m.resimulated) $("robot-caption").textContent += " (re-simulated)";
        for (const s of list) playback.add(s);
        if (m.done) playback.finish();
        land();
      }
      break;
    }
    case "end":
      if (state.liveRobot && m.id === state.liveRobot.id) state.liveDone = true;
      if (playback.robot && m.id === playback.robot.id && !playback.robot.replay) { playback.finish(); land(); }
      break;
    case "stats": state.stats = m; break;
    case "error": $("robot-caption").textContent = "server: " + m.what; break;
  }
}

function connect() {
  const status = $("status");
  socket = new WebSocket(`ws://${location.host}/ws`);
  socket.onopen = () => { status.textContent = "connected"; status.className = "status live"; };
  socket.onmessage = (e) => { try { onFrame(JSON.parse(e.data)); } catch (err) { console.error(err); } };
  socket.onclose = () => {
    status.textContent = "disconnected: retrying"; status.className = "status lost";
    setTimeout(connect, 2000);
  };
}

state.moment = parseMoment(location.hash);
if (state.moment) state.following = false;
window.addEventListener("hashchange", () => {
  if (location.hash === state.hash) return;  // the page's own
  state.moment = parseMoment(location.hash);
  if (state.moment) { state.following = false; land(); }
});

function stripEnd() {
  const end = playback.end();
  return state.run ? Math.max(state.run.steps * state.run.dt, end === null ? 0 : end) : null;
}

let lastFrame = performance.now();
function frame(now) {
  // A frame's timestamp may be earlier than the performance.now() taken before it was asked for:
  // never a negative step (the clock would start before the first sample).
  const dt = Math.max(0, Math.min(100, now - lastFrame));
  lastFrame = now;
  const d = playback.advance(dt, now);
  // Paused, the camera sits on the robot (no spring): the picture holds still.
  if (d) scene.place(d.a.c, d.b.c, d.f, !playback.playing);
  scene.render();
  if (!playback.playing || now - state.stripDrawn >= 200) {  // playing, five times a second is enough for the strip
    state.stripDrawn = now;
    strip.draw(playback.samples, playback.simTime, stripEnd());
  }
  timeline.update(state.following, state.hello ? state.hello.mode : "live");
  writeMoment();
  state.frames++; state.fpsFrames++;
  if (now - state.fpsSince >= 1000) {
    state.fps = state.fpsFrames * 1000 / (now - state.fpsSince);
    state.fpsFrames = 0; state.fpsSince = now;
    facts();
  }
  requestAnimationFrame(frame);
}
requestAnimationFrame(frame);

// For tests and measurements (read over the DevTools protocol).
window.robozooView = {
  stats: () => ({
    fps: state.fps, frames: state.frames, framesReceived: state.framesReceived,
    chartPoints: chart.count(), chartGenerations: chart.gens.map((g) => g.g),
    champions: state.champions.length, robot: playback.robot ? playback.robot.id : null,
    spheres: playback.robot ? playback.robot.radius.length : 0, samples: playback.samples.length,
    leaves: playback.robot ? playback.robot.leaf.filter((x) => x).length : 0,
    endTime: playback.samples.length ? playback.samples[playback.samples.length - 1].time : null,
    canvas: (() => { const r = scene.renderer.domElement.getBoundingClientRect();
                     return { x: r.x, y: r.y, width: r.width, height: r.height }; })(),
    simTime: playback.simTime, firstPoseLatencyMs: playback.firstLatencyMs,
    dropped: state.stats ? state.stats.dropped : null, run: state.run ? state.run.id : null,
  }),
  replay,
  /// The data-flow entry point: one frame (an object as in view/state/frames.hpp), from any source.
  feed: onFrame,
  /// Where requests ({"t":"replay","id":N}) go instead of the socket.
  setSender: (f) => { send = f; },
  /// The timeline's state: playhead, what is shown, the cursors drawn.
  timeline: () => ({
    playhead: playback.simTime, index: playback.index, playing: playback.playing, speed: playback.speed,
    loop: playback.loop, following: state.following, robot: playback.robot ? playback.robot.id : null,
    gen: playback.robot ? playback.robot.gen : null, samples: playback.samples.length, start: playback.start(),
    end: playback.end(), done: playback.done, stripCursorX: strip.info.cursorX, chartCursorX: chart.cursorX,
    chartCursor: chart.cursor, stateText: $("tl-state").textContent, hash: location.hash,
    pose: (() => { const p = playback.pose(); return p ? { a: p.a.step, b: p.b.step, f: p.f } : null; })(),
  }),
  play: () => timeline.play(), pause: () => timeline.pause(), seek: (t) => timeline.seek(t),
  step: (n) => timeline.step(n), live: () => backToLive(),
  strip: () => strip.info,
  /// The chart's tick labels (round numbers): {fitness, species, generation}.
  chartTicks: () => chart.tickLabels,
  cppn: () => cppn.counts(),
  /// The box of an element of the page (CSS px), for screenshots.
  rect: (id) => { const r = $(id).getBoundingClientRect(); return { x: r.x, y: r.y, width: r.width, height: r.height }; },
  /// Milliseconds per draw of the 3D view, the strip and the chart (n draws each).
  timeDraw: (n) => {
    const time = (f) => { const t0 = performance.now(); for (let i = 0; i < n; i++) f(); return (performance.now() - t0) / n; };
    const gl = scene.renderer.getContext();
    return { scene: time(() => { scene.render(); gl.finish(); }),
             strip: time(() => strip.redraw()), chart: time(() => chart.draw()) };
  },
};

// Start: an exported file feeds its inlined frames, a served page connects (after every
// declaration above, so that the first frame finds the page ready).
const offline = offlineFrames();
setupSave($("save-html"), () => (playback.robot ? playback.robot.id : null), offline !== null);
if (offline) {
  $("status").textContent = "offline file"; $("status").className = "status live";
  for (const m of offline) onFrame(m);
} else connect();
