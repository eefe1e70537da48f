// Runs the Khronos glTF validator on a .glb/.gltf file.
// Exit 0 only when the report has 0 errors and 0 warnings; prints every message.
// usage: node validate-gltf.js FILE
const fs = require('fs');
const path = require('path');
const validator = require('gltf-validator');

const file = process.argv[2];
if (!file) {
  console.error('usage: node validate-gltf.js FILE');
  process.exit(2);
}
const bytes = new Uint8Array(fs.readFileSync(file));
validator.validateBytes(bytes, {
  uri: path.basename(file),
  maxIssues: 0,
  externalResourceFunction: (uri) => new Promise((resolve, reject) => {
    try { resolve(new Uint8Array(fs.readFileSync(path.join(path.dirname(file), decodeURIComponent(uri))))); }
    catch (e) { reject(e.toString()); }
  }),
}).then((report) => {
  const n = report.issues;
  for (const m of n.messages) console.log(`${file}: ${['error', 'warning', 'info', 'hint'][m.severity]}: ${m.code} ${m.pointer || ''} ${m.message}`);
  console.log(`${file}: ${n.numErrors} errors, ${n.numWarnings} warnings, ${n.numInfos} infos, ${n.numHints} hints`);
  process.exit(n.numErrors === 0 && n.numWarnings === 0 ? 0 : 1);
}, (error) => {
  console.error(`${file}: validator failed: ${error}`);
  process.exit(1);
});
