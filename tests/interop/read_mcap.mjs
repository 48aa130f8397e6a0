// node read_mcap.mjs FILE.mcap
// Reads an MCAP file twice with @mcap/core — record by record (McapStreamReader, chunk CRCs
// checked) and through its summary and indexes (McapIndexedReader) — and decodes every message
// with @foxglove/rosmsg2-serialization from the schema the file carries. Prints JSON: per topic
// the type, count, first and last log time and the first message decoded; exits 1 on any error.
import fs from "node:fs";
import { McapIndexedReader, McapStreamReader } from "@mcap/core";
import zstd from "@foxglove/wasm-zstd";
import lz4 from "@foxglove/wasm-lz4";
import { readerFor } from "./ros_types.mjs";

await zstd.isLoaded;
await lz4.isLoaded;
const decompressHandlers = {
  zstd: (data, size) => zstd.decompress(data, Number(size)),
  lz4: (data, size) => lz4(data, Number(size)),
};
const bytes = fs.readFileSync(process.argv[2]);
const plain = (value) => JSON.parse(JSON.stringify(value, (k, v) =>
  typeof v === "bigint" ? v.toString() : ArrayBuffer.isView(v) ? Array.from(v) : v));

const stream = new McapStreamReader({ decompressHandlers, validateCrcs: true });
stream.append(bytes);
const schemas = new Map(), channels = new Map(), topics = {};
const readers = new Map();
let header;
for (let record; (record = stream.nextRecord());) {
  if (record.type === "Header") header = record;
  if (record.type === "Schema") schemas.set(record.id, record);
  if (record.type === "Channel") channels.set(record.id, record);
  if (record.type !== "Message") continue;
  const channel = channels.get(record.channelId);
  const schema = schemas.get(channel.schemaId);
  if (!readers.has(channel.id)) readers.set(channel.id, readerFor(new TextDecoder().decode(schema.data)));
  const decoded = readers.get(channel.id).readMessage(record.data);
  const entry = (topics[channel.topic] ??= {
    type: schema.name, encoding: schema.encoding, message_encoding: channel.messageEncoding,
    qos: channel.metadata.get("offered_qos_profiles") ?? "", count: 0, first: plain(decoded),
    first_log_time: record.logTime.toString(),
  });
  entry.count++;
  entry.last_log_time = record.logTime.toString();
}
if (!stream.done()) throw new Error("the stream reader did not reach the end magic");

const indexed = await McapIndexedReader.Initialize({
  readable: { size: async () => BigInt(bytes.length),
              read: async (offset, size) => bytes.subarray(Number(offset), Number(offset + size)) },
  decompressHandlers,
});
let indexedCount = 0, previous = -1n;
for await (const message of indexed.readMessages({ validateCrcs: true })) {
  if (message.logTime < previous) throw new Error("indexed messages out of log-time order");
  previous = message.logTime;
  indexedCount++;
}
console.log(JSON.stringify({
  profile: header.profile, library: header.library,
  statistics_message_count: indexed.statistics ? indexed.statistics.messageCount.toString() : null,
  chunk_count: indexed.chunkIndexes.length, indexed_message_count: indexedCount, topics,
}, null, 1));
