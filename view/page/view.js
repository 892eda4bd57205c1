// robozoo-view's page: one WebSocket to the server (frames described in
// view/frames.hpp), the 3D view, the chart, the strip, the run's facts and its
// champions. It opens on the newest champion and plays it: no mouse needed.
import { Scene } from "/scene.js";
import { Chart } from "/chart.js";
import { Strip } from "/strip.js";
import { Playback } from "/playback.js";
import { offlineFrames, setupSave } from "/offline.js";

const $ = (id) => document.getElementById(id);
const scene = new Scene($("stage"));
const chart = new Chart($("chart"));
const strip = new Strip($("strip"), $("strip-key"));
const playback = new Playback();

const state = {
  hello: null, run: null, last: null, champions: [], stats: null,
  following: true,      // show the newest champion as it arrives (false while a replay plays)
  liveRobot: null,      // the newest live robot and its samples, kept while a replay plays
  liveSamples: [], liveDone: false,
  frames: 0, stripDrawn: 0, fps: 0, fpsFrames: 0, fpsSince: performance.now(), framesReceived: 0,
};

const num = (v, d = 2) => (typeof v === "number" && isFinite(v) ? v.toFixed(d) : "–");

function showRobot(robot) {
  playback.clear(robot);
  scene.setRobot(robot.radius, robot.leaf, robot.start);
  strip.setRobot(robot);
  const r = robot.replay ? " (replay" + (robot.resimulated ? ", re-simulated" : "") + ")" : "";
  $("robot-caption").textContent = `genome ${robot.id}, generation ${robot.gen}, fitness ${num(robot.fitness)}${r}`;
  $("follow-live").hidden = state.following;
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
  b.addEventListener("click", () => replay(c.id));
  li.appendChild(b);
  $("champions").prepend(li);
  markShown();
}

function markShown() {
  const id = playback.robot ? playback.robot.id : null;
  for (const li of $("champions").children) li.classList.toggle("shown", Number(li.dataset.id) === id);
}

let socket = null;
function replay(id) {
  if (socket && socket.readyState === WebSocket.OPEN) socket.send(JSON.stringify({ t: "replay", id }));
}

function backToLive() {
  state.following = true;
  if (state.liveRobot) {
    showRobot(state.liveRobot);
    for (const s of state.liveSamples) playback.add(s);
    if (state.liveDone) playback.finish();
  }
}
$("follow-live").addEventListener("click", backToLive);

function resetRun() {
  state.run = null; state.last = null; state.champions = [];
  state.liveRobot = null; state.liveSamples = []; state.liveDone = false; state.following = true;
  $("champions").replaceChildren();
  chart.clear();
}

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
      if (m.replay) { state.following = false; showRobot(m); break; }
      state.liveRobot = m; state.liveSamples = []; state.liveDone = false;
      if (state.following) showRobot(m);
      break;
    case "pose": {
      const s = sampleOf(m);
      if (state.liveRobot && m.id === state.liveRobot.id) state.liveSamples.push(s);
      if (playback.robot && m.id === playback.robot.id) playback.add(s);
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
      }
      break;
    }
    case "end":
      if (state.liveRobot && m.id === state.liveRobot.id) state.liveDone = true;
      if (playback.robot && m.id === playback.robot.id && !playback.robot.replay) playback.finish();
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
const offline = offlineFrames();
setupSave($("save-html"), () => (playback.robot ? playback.robot.id : null), offline !== null);
if (offline) {
  $("status").textContent = "offline file"; $("status").className = "status live";
  for (const m of offline) onFrame(m);
} else connect();

let lastFrame = performance.now();
function frame(now) {
  const dt = Math.min(100, now - lastFrame);
  lastFrame = now;
  const d = playback.advance(dt, now);
  if (d) scene.place(d.a.c, d.b.c, d.f);
  scene.render();
  if (now - state.stripDrawn >= 200) {  // five times a second is enough for the strip
    state.stripDrawn = now;
    strip.draw(playback.samples, playback.index,
               state.run ? Math.max(state.run.steps * state.run.dt, playback.samples.length ? playback.samples[playback.samples.length - 1].time : 0) : null);
  }
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
  /// Milliseconds per draw of the 3D view, the strip and the chart (n draws each).
  timeDraw: (n) => {
    const time = (f) => { const t0 = performance.now(); for (let i = 0; i < n; i++) f(); return (performance.now() - t0) / n; };
    const gl = scene.renderer.getContext();
    return { scene: time(() => { scene.render(); gl.finish(); }),
             strip: time(() => strip.draw(playback.samples, playback.index, null)), chart: time(() => chart.draw()) };
  },
};
