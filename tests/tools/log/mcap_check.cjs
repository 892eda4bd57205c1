// Checks an MCAP file robozoo-log export wrote, with the format's own library
// (@mcap/core, Foxglove's): the file opens indexed (summary CRC checked), every
// chunk's CRC holds (read through the chunk indexes, and by readMessages), the
// data section's CRC holds, every message reads back, counts per channel match
// robozoo-log summary --json and the file's statistics, every JSON message
// validates (ajv) against its channel's schema, scenes also against Foxglove's
// own foxglove.SceneUpdate schema, and each scene's robot has as many spheres
// as its morphology, with the ground and the target beside it.
//   node mcap_check.cjs NODE_MODULES FILE.mcap SUMMARY.json
// Prints one JSON line of what it saw; exit 0 when every check holds.
"use strict";
const fs = require("node:fs/promises");
const path = require("node:path");
const { createRequire } = require("node:module");
const { openReadable } = require("../../../tools/log/mcap_readable.cjs");

const [modules, file, summaryPath] = process.argv.slice(2);
if (!modules || !file || !summaryPath) {
  console.error("usage: node mcap_check.cjs NODE_MODULES FILE.mcap SUMMARY.json");
  process.exit(2);
}
const req = createRequire(path.join(path.resolve(modules), "x.js"));
const { McapIndexedReader } = req("@mcap/core");
const { loadDecompressHandlers } = req("@mcap/support");
const { crc32 } = req("@foxglove/crc");
const Ajv = req("ajv");
const foxglove = req("@foxglove/schemas/jsonschema");

const failures = [];
function check(ok, what) {
  if (!ok) failures.push(what);
}

function u64(view, at) {
  return view.getBigUint64(at, true);
}

async function main() {
  const readable = await openReadable(file);
  const decompressHandlers = await loadDecompressHandlers();
  const reader = await McapIndexedReader.Initialize({ readable, decompressHandlers });

  // Data section CRC: every byte before the Data End record.
  const head = await readable.read(0n, reader.dataEndOffset);
  check(reader.dataSectionCrc !== undefined, "the Data End record has no CRC");
  check(crc32(head) === reader.dataSectionCrc, `data section CRC ${crc32(head)} != ${reader.dataSectionCrc}`);

  // Every chunk, through its index: record layout as the spec gives it, CRC of the records.
  check(reader.chunkIndexes.length > 0, "no chunk indexes");
  for (const ci of reader.chunkIndexes) {
    const bytes = await readable.read(ci.chunkStartOffset, ci.chunkLength);
    const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    check(bytes[0] === 0x06, `chunk index points at opcode ${bytes[0]}`);
    let at = 9;
    const start = u64(view, at), end = u64(view, at + 8), usize = u64(view, at + 16);
    const crc = view.getUint32(at + 24, true);
    at += 28;
    const clen = view.getUint32(at, true);
    const compression = Buffer.from(bytes.subarray(at + 4, at + 4 + clen)).toString();
    at += 4 + clen;
    const rlen = Number(u64(view, at));
    const records = bytes.subarray(at + 8, at + 8 + rlen);
    const raw = compression === "" ? records : decompressHandlers[compression](records, usize);
    check(BigInt(raw.byteLength) === usize, `chunk at ${ci.chunkStartOffset}: ${raw.byteLength} bytes, not ${usize}`);
    check(crc !== 0 && crc32(raw) === crc, `chunk at ${ci.chunkStartOffset}: CRC mismatch`);
    check(start === ci.messageStartTime && end === ci.messageEndTime, "chunk and chunk index times differ");
    check(compression === ci.compression, "chunk and chunk index compression differ");
  }

  // Schemas compiled by ajv; Foxglove's own SceneUpdate schema beside ours.
  const ajv = new Ajv({ allErrors: false, strict: false });
  const validators = new Map();
  for (const [id, channel] of reader.channelsById) {
    const schema = reader.schemasById.get(channel.schemaId);
    check(schema && schema.encoding === "jsonschema", `${channel.topic}: no jsonschema`);
    check(channel.messageEncoding === "json", `${channel.topic}: encoding ${channel.messageEncoding}`);
    validators.set(id, ajv.compile(JSON.parse(new TextDecoder().decode(schema.data))));
  }
  const officialScene = ajv.compile(foxglove.SceneUpdate);

  const counts = {};
  const morphologies = new Map();
  const decoder = new TextDecoder();
  let scenes = 0, lastTime = -1n, invalid = 0;
  for await (const m of reader.readMessages({ validateCrcs: true })) {
    const channel = reader.channelsById.get(m.channelId);
    counts[channel.topic] = (counts[channel.topic] || 0) + 1;
    check(m.logTime >= lastTime, `${channel.topic}: messages out of log-time order`);
    lastTime = m.logTime;
    const msg = JSON.parse(decoder.decode(m.data));
    const validate = validators.get(m.channelId);
    if (!validate(msg)) {
      if (invalid++ < 3) failures.push(`${channel.topic} #${m.sequence}: ${ajv.errorsText(validate.errors)}`);
    }
    if (channel.topic === "ROBOZOO_MORPHOLOGY") morphologies.set(`${msg.run_id}/${msg.genome_id}`, msg.num_spheres);
    if (reader.schemasById.get(channel.schemaId).name === "foxglove.SceneUpdate") {
      ++scenes;
      if (!officialScene(msg) && invalid++ < 3) failures.push(`scene: Foxglove's schema: ${ajv.errorsText(officialScene.errors)}`);
      const ids = msg.entities.map((e) => e.id).join(",");
      check(ids === "robot,ground,target", `scene entities ${ids}`);
      const robot = msg.entities[0];
      const meta = Object.fromEntries(robot.metadata.map((kv) => [kv.key, kv.value]));
      const want = morphologies.get(`${meta.run_id}/${meta.genome_id}`);
      check(want !== undefined && robot.spheres.length === want,
            `scene of genome ${meta.genome_id}: ${robot.spheres.length} spheres, morphology ${want}`);
      check(msg.entities[1].cubes.length === 1 && msg.entities[2].spheres.length === 1, "ground or target missing");
    }
  }
  check(invalid === 0, `${invalid} messages do not validate`);

  // Counts: the log's (robozoo-log summary --json) and the file's statistics.
  const summary = JSON.parse(await fs.readFile(summaryPath, "utf8"));
  for (const [channel, c] of Object.entries(summary.channels))
    check(counts[channel] === c.messages, `${channel}: ${counts[channel]} messages, the log has ${c.messages}`);
  const gens = summary.channels.ROBOZOO_GENERATION ? summary.channels.ROBOZOO_GENERATION.messages : 0;
  const poses = summary.channels.ROBOZOO_POSE ? summary.channels.ROBOZOO_POSE.messages : 0;
  check((counts["/generation/stats"] || 0) === gens, "one /generation/stats per generation");
  check(scenes === poses, `${scenes} scenes for ${poses} poses`);
  const total = Object.values(counts).reduce((a, b) => a + b, 0);
  check(reader.statistics && reader.statistics.messageCount === BigInt(total), "statistics' message count");
  for (const [id, n] of reader.statistics.channelMessageCounts)
    check(Number(n) === counts[reader.channelsById.get(id).topic], "statistics' per-channel count");

  await readable.close();
  console.log(JSON.stringify({ file, chunks: reader.chunkIndexes.length, messages: total, scenes, counts,
                               compression: reader.chunkIndexes[0].compression, failures }));
  process.exit(failures.length === 0 ? 0 : 1);
}

main().catch((e) => {
  console.error(`mcap_check: ${file}: ${e.stack || e}`);
  process.exit(1);
});
