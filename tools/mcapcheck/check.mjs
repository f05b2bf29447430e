#!/usr/bin/env node
// Independent check of an MCAP file: reads it with Foxglove's TypeScript reader (@mcap/core),
// once through the summary (McapIndexedReader: footer -> summary -> chunk indexes -> chunks) and
// once front to back (McapStreamReader), with CRC validation on. Prints one line of JSON:
//   {"file":..., "messages":N, "chunks":N, "channels":[{"topic","schema","count"}...], ...}
// and exits 0 only if both readers succeed and agree with each other and with the file's
// Statistics record. Exit 1: disagreement; exit 2: a reader threw (corrupt or cut-off file).
//
// usage: node check.mjs FILE
import { open, readFile } from "node:fs/promises";
import { McapIndexedReader, McapStreamReader } from "@mcap/core";
import { decompress as zstdDecompress } from "fzstd";
import lz4 from "lz4js";

const decompressHandlers = {
  zstd: (buffer) => zstdDecompress(buffer),
  lz4: (buffer, decompressedSize) => lz4.decompress(buffer, Number(decompressedSize)),
};

// IReadable over a file handle: the indexed reader only reads what the summary points to.
async function fileReadable(path) {
  const handle = await open(path, "r");
  const size = (await handle.stat()).size;
  return {
    handle,
    size: async () => BigInt(size),
    read: async (offset, length) => {
      const out = new Uint8Array(Number(length));
      let done = 0;
      while (done < out.length) {
        const { bytesRead } = await handle.read(out, done, out.length - done, Number(offset) + done);
        if (bytesRead === 0) throw new Error(`read past end of file at byte ${Number(offset) + done}`);
        done += bytesRead;
      }
      return out;
    },
  };
}

function tally(counts, channelId, data) {
  const entry = counts.get(channelId) ?? { count: 0, bytes: 0 };
  entry.count += 1;
  entry.bytes += data.byteLength;
  counts.set(channelId, entry);
}

async function readIndexed(path) {
  const readable = await fileReadable(path);
  try {
    const reader = await McapIndexedReader.Initialize({ readable, decompressHandlers });
    const counts = new Map();
    let lastLogTime = -1n;
    let outOfOrder = 0;
    for await (const m of reader.readMessages({ validateCrcs: true })) {
      tally(counts, m.channelId, m.data);
      if (m.logTime < lastLogTime) outOfOrder += 1;
      lastLogTime = m.logTime;
    }
    return {
      header: reader.header,
      channels: reader.channelsById,
      schemas: reader.schemasById,
      statistics: reader.statistics,
      chunks: reader.chunkIndexes.length,
      counts,
      outOfOrder,
    };
  } finally {
    await readable.handle.close();
  }
}

async function readStream(path) {
  const stream = new McapStreamReader({ decompressHandlers, validateCrcs: true });
  stream.append(await readFile(path));
  const counts = new Map();
  const channels = new Map();
  let chunks = 0;
  for (let record; (record = stream.nextRecord()); ) {
    if (record.type === "Message") tally(counts, record.channelId, record.data);
    else if (record.type === "Channel") channels.set(record.id, record);
    else if (record.type === "ChunkIndex") chunks += 1;
  }
  if (!stream.done()) throw new Error("stream reader: file ends before its footer and magic");
  return { counts, channels, chunks };
}

function compare(indexed, streamed) {
  const problems = [];
  const ids = new Set([...indexed.counts.keys(), ...streamed.counts.keys()]);
  for (const id of ids) {
    const a = indexed.counts.get(id) ?? { count: 0, bytes: 0 };
    const b = streamed.counts.get(id) ?? { count: 0, bytes: 0 };
    if (a.count !== b.count || a.bytes !== b.bytes) {
      problems.push(`channel ${id}: indexed ${a.count} msgs/${a.bytes} B, stream ${b.count}/${b.bytes}`);
    }
    const topicA = indexed.channels.get(id)?.topic;
    const topicB = streamed.channels.get(id)?.topic;
    if (topicA !== topicB) problems.push(`channel ${id}: topic ${topicA} vs ${topicB}`);
  }
  const stats = indexed.statistics;
  if (stats) {
    const total = [...indexed.counts.values()].reduce((s, c) => s + c.count, 0);
    if (Number(stats.messageCount) !== total) {
      problems.push(`statistics say ${stats.messageCount} messages, read ${total}`);
    }
    for (const [id, n] of stats.channelMessageCounts) {
      const got = indexed.counts.get(id)?.count ?? 0;
      if (Number(n) !== got) problems.push(`statistics: channel ${id} ${n} msgs, read ${got}`);
    }
    if (stats.chunkCount !== indexed.chunks) {
      problems.push(`statistics say ${stats.chunkCount} chunks, summary indexes ${indexed.chunks}`);
    }
  } else {
    problems.push("no Statistics record in the summary");
  }
  if (indexed.outOfOrder > 0) problems.push(`${indexed.outOfOrder} messages out of log-time order`);
  return problems;
}

async function main() {
  const path = process.argv[2];
  if (!path) {
    console.error("usage: node check.mjs FILE.mcap");
    process.exit(2);
  }
  let indexed, streamed;
  try {
    indexed = await readIndexed(path);
    streamed = await readStream(path);
  } catch (e) {
    console.error(JSON.stringify({ file: path, error: String(e?.message ?? e) }));
    process.exit(2);
  }
  const problems = compare(indexed, streamed);
  const channels = [...indexed.channels.values()]
    .sort((a, b) => a.id - b.id)
    .map((c) => ({
      topic: c.topic,
      schema: indexed.schemas.get(c.schemaId)?.name ?? "",
      count: indexed.counts.get(c.id)?.count ?? 0,
    }));
  const report = {
    file: path,
    profile: indexed.header.profile,
    library: indexed.header.library,
    messages: channels.reduce((s, c) => s + c.count, 0),
    chunks: indexed.chunks,
    channels,
    agree: problems.length === 0,
    problems,
  };
  console.log(JSON.stringify(report));
  process.exit(problems.length === 0 ? 0 : 1);
}

await main();
