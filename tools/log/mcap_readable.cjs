// An MCAP file opened for @mcap/core's indexed reader: the IReadable it wants
// (size, and reads at any offset) over a file handle, and close(). Shared by
// tools/log/mcap_frame.cjs and tests/tools/log/mcap_check.cjs.
"use strict";
const fs = require("node:fs/promises");

async function openReadable(file) {
  const handle = await fs.open(file, "r");
  const size = BigInt((await handle.stat()).size);
  return {
    size: async () => size,
    read: async (offset, length) => {
      const buf = Buffer.alloc(Number(length));
      await handle.read(buf, 0, Number(length), Number(offset));
      return new Uint8Array(buf.buffer, buf.byteOffset, buf.byteLength);
    },
    close: () => handle.close(),
  };
}

module.exports = { openReadable };
