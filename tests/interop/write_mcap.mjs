// node write_mcap.mjs BAG_DIR zstd|lz4|none [--no-summary]
// Writes BAG_DIR/<name>_0.mcap with @mcap/core as rosbag2's MCAP plugin lays a bag out (profile
// "ros2", ros2msg schemas, cdr channels with their QoS), chunks compressed as asked; with
// --no-summary the file ends after its data section, like a recording that was cut off.
import fs from "node:fs";
import path from "node:path";
import { McapWriter } from "@mcap/core";
import zstd from "@foxglove/wasm-zstd";
import lz4 from "lz4js";
import { definitions, interopMessages, qos } from "./ros_types.mjs";

const [dir, compression, flag] = process.argv.slice(2);
const noSummary = flag === "--no-summary";
await zstd.isLoaded;
const compressChunk = {
  zstd: (data) => ({ compression: "zstd", compressedData: zstd.compress(data, 3) }),
  lz4: (data) => ({ compression: "lz4", compressedData: Uint8Array.from(lz4.compress(data)) }),
  none: undefined,
}[compression];

const chunks = [];
let position = 0n;
const writable = {
  write: async (buffer) => { chunks.push(Buffer.from(buffer)); position += BigInt(buffer.byteLength); },
  position: () => position,
};
const writer = new McapWriter({
  writable, chunkSize: 16 * 1024, compressChunk,
  useSummaryOffsets: !noSummary, useStatistics: !noSummary, useChunkIndex: !noSummary,
  repeatSchemas: !noSummary, repeatChannels: !noSummary,
  useMessageIndex: !noSummary, useAttachmentIndex: false, useMetadataIndex: false,
});
await writer.start({ profile: "ros2", library: "interop writer" });
const channels = new Map();
for (const m of interopMessages()) {
  if (!channels.has(m.topic)) {
    const schemaId = await writer.registerSchema({
      name: m.type, encoding: "ros2msg", data: new TextEncoder().encode(definitions[m.type]),
    });
    channels.set(m.topic, await writer.registerChannel({
      topic: m.topic, schemaId, messageEncoding: "cdr",
      metadata: new Map([["offered_qos_profiles", qos]]),
    }));
  }
  await writer.addMessage({
    channelId: channels.get(m.topic), sequence: 0, logTime: m.logTime, publishTime: m.logTime,
    data: m.data,
  });
}
await writer.end();
let bytes = Buffer.concat(chunks);
if (noSummary) {
  // Keep the data section only: up to and including the DataEnd record.
  let at = 8;
  for (;;) {
    const length = Number(bytes.readBigUInt64LE(at + 1));
    at += 9 + length;
    if (bytes[at - 9 - length] === 0x0f) break;
  }
  bytes = bytes.subarray(0, at);
}
fs.mkdirSync(dir, { recursive: true });
fs.writeFileSync(path.join(dir, `${path.basename(dir)}_0.mcap`), bytes);
