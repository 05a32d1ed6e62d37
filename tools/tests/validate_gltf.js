#!/usr/bin/env node
// validate_gltf.js - checks a .gltf or .glb with the Khronos glTF-Validator
// (npm package gltf-validator), the validator that glTF viewers and the
// Khronos sample models are checked against. test_gltf_round_trip runs it on
// uv_unwrap's outputs; scripts/install_gltf_validator.sh installs the package.
//   GLTF_VALIDATOR_DIR=build/gltf-validator node tools/tests/validate_gltf.js out.glb
// Prints "errors=N warnings=N infos=N" and every error and warning.
// Exit status: 0 no error and no warning but the allowed ones below;
// 1 an error or another warning; 2 the validator cannot run (not installed,
// unreadable file).
'use strict';
const fs = require('fs'), path = require('path');

// Warnings allowed in uv_unwrap's outputs, each with its reason. None so far:
// uv_unwrap keeps the input's scene, and the round trip's input is clean.
const allowed_warnings = {
  // 'CODE': 'why uv_unwrap cannot avoid it',
};

const roots = [process.env.GLTF_VALIDATOR_DIR, process.cwd(), __dirname].filter(Boolean);
let validator;
for (const r of roots) {
  try { validator = require(require.resolve('gltf-validator', { paths: [r, path.join(r, 'node_modules')] })); break; } catch (e) {}
}
if (!validator) {
  console.error('validate_gltf: the npm package gltf-validator is not installed in ' +
                (process.env.GLTF_VALIDATOR_DIR || '(GLTF_VALIDATOR_DIR unset)') +
                ' (scripts/install_gltf_validator.sh installs it)');
  process.exit(2);
}
const file = process.argv[2];
if (!file) { console.error('usage: validate_gltf.js FILE.gltf|FILE.glb'); process.exit(2); }
let bytes;
try { bytes = fs.readFileSync(file); } catch (e) { console.error('validate_gltf: ' + e); process.exit(2); }
const dir = path.dirname(file);
validator.validateBytes(new Uint8Array(bytes), {
  uri: path.basename(file),
  maxIssues: 0, // all of them
  externalResourceFunction: (uri) => new Promise((ok, fail) =>
    fs.readFile(path.join(dir, decodeURIComponent(uri)), (e, d) => (e ? fail(e.toString()) : ok(new Uint8Array(d))))),
}).then((report) => {
  const issues = report.issues;
  console.log(`errors=${issues.numErrors} warnings=${issues.numWarnings} infos=${issues.numInfos}`);
  let refused = 0;
  for (const m of issues.messages.filter((m) => m.severity <= 1)) {
    const kind = m.severity === 0 ? 'error' : 'warning';
    const reason = m.severity === 1 ? allowed_warnings[m.code] : undefined;
    if (!reason) ++refused;
    console.log(`  ${kind} ${m.code} ${m.pointer || ''}: ${m.message}` + (reason ? ` (allowed: ${reason})` : ''));
  }
  process.exit(refused ? 1 : 0);
}, (e) => { console.error('validate_gltf: the validator failed: ' + e); process.exit(2); });
