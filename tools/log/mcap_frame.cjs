// One frame of an MCAP file robozoo-log export wrote, drawn as SVG from the
// file alone: the N-th foxglove.SceneUpdate (default the last), read with
// @mcap/core, its spheres in an axonometric view over a grid on the ground,
// the target's direction marked. For docs/foxglove.md, where Foxglove itself
// cannot run; chromium --headless --screenshot turns the SVG into a PNG.
//   node tools/log/mcap_frame.cjs NODE_MODULES FILE.mcap OUT.svg [--index N] [--topic /robot/scene]
"use strict";
const fs = require("node:fs/promises");
const path = require("node:path");
const { createRequire } = require("node:module");
const { openReadable } = require("./mcap_readable.cjs");

const USAGE = "usage: node tools/log/mcap_frame.cjs NODE_MODULES FILE.mcap OUT.svg [--index N] [--topic T]\n" +
  "  draws the N-th message (default -1: the last) of topic T (default /robot/scene) as SVG";
function usage(why) {
  console.error(`mcap_frame: ${why}\n${USAGE}`);
  process.exit(2);
}
const args = process.argv.slice(2);
const positional = [];
let index = -1, topic = "/robot/scene";
for (let i = 0; i < args.length; ++i) {
  if (args[i] === "--index") index = Number(args[++i]);
  else if (args[i] === "--topic") topic = args[++i];
  else if (args[i] === "--help" || args[i] === "-h") {
    console.log(USAGE);
    process.exit(0);
  }
  else if (args[i].startsWith("-")) usage(`unknown option ${args[i]}`);
  else positional.push(args[i]);
}
if (positional.length !== 3 || !Number.isInteger(index)) usage("three arguments expected");
const [modules, file, out] = positional;
const req = createRequire(path.join(path.resolve(modules), "x.js"));
const { McapIndexedReader } = req("@mcap/core");
const { loadDecompressHandlers } = req("@mcap/support");

// View: azimuth and elevation of the eye (degrees), as robozoo-render's default camera.
const AZIMUTH = (-62 * Math.PI) / 180, ELEVATION = (24 * Math.PI) / 180;
const right = [-Math.sin(AZIMUTH), Math.cos(AZIMUTH), 0];
const up = [-Math.cos(AZIMUTH) * Math.sin(ELEVATION), -Math.sin(AZIMUTH) * Math.sin(ELEVATION), Math.cos(ELEVATION)];
const toward = [Math.cos(AZIMUTH) * Math.cos(ELEVATION), Math.sin(AZIMUTH) * Math.cos(ELEVATION), Math.sin(ELEVATION)];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const rgb = (c, k = 1) => `rgb(${[c.r, c.g, c.b].map((v) => Math.round(Math.min(1, v * k) * 255)).join(",")})`;

async function main() {
  const readable = await openReadable(file);
  const reader = await McapIndexedReader.Initialize({ readable, decompressHandlers: await loadDecompressHandlers() });
  const scenes = [];
  for await (const m of reader.readMessages({ topics: [topic] })) scenes.push(m);
  await readable.close();
  if (scenes.length === 0) throw new Error(`no messages on ${topic}`);
  const m = scenes[index < 0 ? scenes.length + index : index];
  if (!m) throw new Error(`no message ${index} on ${topic} (it has ${scenes.length})`);
  const scene = JSON.parse(new TextDecoder().decode(m.data));
  const byId = Object.fromEntries(scene.entities.map((e) => [e.id, e]));
  const robot = byId.robot, target = byId.target.spheres[0];
  const meta = Object.fromEntries(robot.metadata.map((kv) => [kv.key, kv.value]));

  const centre = [0, 1, 2].map((k) => robot.spheres.reduce((s, p) => s + [p.pose.position.x, p.pose.position.y, p.pose.position.z][k], 0) / robot.spheres.length);
  const W = 960, H = 600, scale = 150;
  const project = (p) => [W / 2 + scale * (dot(p, right) - dot(centre, right)), H * 0.58 - scale * (dot(p, up) - dot(centre, up))];
  const parts = [];
  // Ground grid, 0.5 m spacing, 3 m around the robot.
  const gx = Math.round(centre[0] * 2) / 2, gy = Math.round(centre[1] * 2) / 2;
  const groundColour = rgb(byId.ground.cubes[0].color);
  const corners = [[-3, -3], [3, -3], [3, 3], [-3, 3]].map(([dx, dy]) => project([gx + dx, gy + dy, 0]));
  parts.push(`<polygon points="${corners.map((c) => c.join(",")).join(" ")}" fill="${groundColour}"/>`);
  for (let k = -6; k <= 6; ++k) {
    const d = k / 2, w = k % 2 === 0 ? 1.2 : 0.6;
    for (const [a, b] of [[[gx + d, gy - 3, 0], [gx + d, gy + 3, 0]], [[gx - 3, gy + d, 0], [gx + 3, gy + d, 0]]]) {
      const [p, q] = [project(a), project(b)];
      parts.push(`<line x1="${p[0]}" y1="${p[1]}" x2="${q[0]}" y2="${q[1]}" stroke="#9a9890" stroke-width="${w}"/>`);
    }
  }
  // Towards the target: an arrow on the ground from the robot.
  const tp = [target.pose.position.x, target.pose.position.y, 0];
  const dir = [tp[0] - centre[0], tp[1] - centre[1]];
  const len = Math.hypot(dir[0], dir[1]);
  const a0 = project([centre[0], centre[1], 0]);
  const a1 = project([centre[0] + (2.4 * dir[0]) / len, centre[1] + (2.4 * dir[1]) / len, 0]);
  parts.push(`<line x1="${a0[0]}" y1="${a0[1]}" x2="${a1[0]}" y2="${a1[1]}" stroke="${rgb(target.color)}" stroke-width="5" marker-end="url(#head)"/>`);
  parts.push(`<text x="${a1[0] + 8}" y="${a1[1] + 4}" font-size="15" fill="#7a5a10">target, ${len.toFixed(1)} m</text>`);
  // Spheres far to near, each with a shaded fill and a shadow on the ground.
  const spheres = robot.spheres.map((s) => ({ s, p: [s.pose.position.x, s.pose.position.y, s.pose.position.z] }));
  for (const { s, p } of spheres) {
    const c = project([p[0], p[1], 0]), r = (scale * s.size.x) / 2;
    parts.push(`<ellipse cx="${c[0]}" cy="${c[1]}" rx="${r}" ry="${r * Math.sin(ELEVATION)}" fill="black" opacity="0.18"/>`);
  }
  spheres.sort((a, b) => dot(a.p, toward) - dot(b.p, toward));
  let gradients = "";
  spheres.forEach(({ s, p }, i) => {
    const c = project(p), r = (scale * s.size.x) / 2;
    gradients += `<radialGradient id="g${i}" cx="0.35" cy="0.3" r="0.75"><stop offset="0" stop-color="${rgb(s.color, 1.6)}"/><stop offset="0.55" stop-color="${rgb(s.color)}"/><stop offset="1" stop-color="${rgb(s.color, 0.45)}"/></radialGradient>`;
    parts.push(`<circle cx="${c[0]}" cy="${c[1]}" r="${r}" fill="url(#g${i})" stroke="#222" stroke-width="1"/>`);
  });
  const t = Number(m.logTime) / 1e9;
  const caption = `${path.basename(file)} · ${topic} #${m.sequence} · log time ${t.toFixed(3)} s · run ${meta.run_id}, generation ${meta.generation}, genome ${meta.genome_id}, step ${meta.step} · ${robot.spheres.length} spheres`;
  const svg = `<svg xmlns="http://www.w3.org/2000/svg" width="${W}" height="${H}" viewBox="0 0 ${W} ${H}" font-family="DejaVu Sans, sans-serif">
<defs><linearGradient id="sky" x1="0" y1="0" x2="0" y2="1"><stop offset="0" stop-color="#96b4d7"/><stop offset="1" stop-color="#e8ecf0"/></linearGradient>
<marker id="head" markerWidth="6" markerHeight="6" refX="3" refY="3" orient="auto"><path d="M0,0 L6,3 L0,6 z" fill="${rgb(target.color)}"/></marker>${gradients}</defs>
<rect width="${W}" height="${H}" fill="url(#sky)"/>
${parts.join("\n")}
<rect x="0" y="${H - 30}" width="${W}" height="30" fill="white" opacity="0.8"/>
<text x="12" y="${H - 10}" font-size="13" fill="#222">${caption}</text>
</svg>
`;
  await fs.writeFile(out, svg);
  console.log(`${out}: ${caption}`);
}

main().catch((e) => {
  console.error(`mcap_frame: ${file}: ${e.message || e}`);
  process.exit(1);
});
