// node write_db3.mjs BAG_DIR
// Writes BAG_DIR/<name>_0.db3 with sql.js in rosbag2's sqlite3 layout (schema version 4, as
// Iron and later write it), holding the same messages as write_mcap.mjs, and no metadata.yaml.
import fs from "node:fs";
import path from "node:path";
import initSqlJs from "sql.js";
import { definitions, interopMessages, qos } from "./ros_types.mjs";

const dir = process.argv[2];
const SQL = await initSqlJs();
const db = new SQL.Database();
db.run(`
CREATE TABLE schema(schema_version INTEGER PRIMARY KEY, ros_distro TEXT NOT NULL);
CREATE TABLE metadata(id INTEGER PRIMARY KEY, metadata_version INTEGER NOT NULL, metadata TEXT NOT NULL);
CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL,
  serialization_format TEXT NOT NULL, offered_qos_profiles TEXT NOT NULL, type_description_hash TEXT NOT NULL);
CREATE TABLE message_definitions(id INTEGER PRIMARY KEY, topic_type TEXT NOT NULL, encoding TEXT NOT NULL,
  encoded_message_definition TEXT NOT NULL, type_description_hash TEXT NOT NULL);
CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL, timestamp INTEGER NOT NULL, data BLOB NOT NULL);
CREATE INDEX timestamp_idx ON messages (timestamp ASC);
INSERT INTO schema VALUES (4, 'jazzy');`);
const topicIds = new Map();
for (const m of interopMessages()) {
  if (!topicIds.has(m.topic)) {
    const id = topicIds.size + 7;  // ids need not start at 1
    db.run("INSERT INTO topics VALUES (?, ?, ?, 'cdr', ?, '')", [id, m.topic, m.type, qos]);
    db.run("INSERT INTO message_definitions (topic_type, encoding, encoded_message_definition, " +
           "type_description_hash) VALUES (?, 'ros2msg', ?, '')", [m.type, definitions[m.type]]);
    topicIds.set(m.topic, id);
  }
  // sql.js binds integers as doubles: write the stamp as text and let SQLite convert it.
  db.run("INSERT INTO messages (topic_id, timestamp, data) VALUES (?, CAST(? AS INTEGER), ?)",
         [topicIds.get(m.topic), m.logTime.toString(), m.data]);
}
fs.mkdirSync(dir, { recursive: true });
fs.writeFileSync(path.join(dir, `${path.basename(dir)}_0.db3`), Buffer.from(db.export()));
