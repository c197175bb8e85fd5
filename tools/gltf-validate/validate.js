#!/usr/bin/env node
// Validates GLB files with the Khronos glTF validator (gltf-validator, pinned in package-lock.json)
// and checks the meshes fsdb promises: every name given after --meshes is a mesh of the file, or
// listed in scenes[0].extras.empty (a bound with no surface at that level).
// Usage: node validate.js FILE.glb... [--meshes lower,upper]
// Exit 0: every file valid (no errors; warnings and infos are printed); 1: otherwise.
'use strict';
const fs = require('fs');
const validator = require('gltf-validator');

function glbJson(bytes) {
  const length = bytes.readUInt32LE(12);
  return JSON.parse(bytes.slice(20, 20 + length).toString('utf8'));
}

async function main() {
  const args = process.argv.slice(2);
  const at = args.indexOf('--meshes');
  const wanted = at >= 0 ? args.splice(at, 2)[1].split(',') : [];
  if (args.length === 0) {
    console.error('usage: node validate.js FILE.glb... [--meshes lower,upper]');
    return 2;
  }
  let failed = 0;
  for (const file of args) {
    const bytes = fs.readFileSync(file);
    const report = await validator.validateBytes(new Uint8Array(bytes), { uri: file, maxIssues: 50 });
    const { numErrors, numWarnings, numInfos } = report.issues;
    for (const m of report.issues.messages) console.log(`${file}: ${m.severity === 0 ? 'error' : 'note'} ${m.code} ${m.pointer || ''}: ${m.message}`);
    const gltf = glbJson(bytes);
    const names = (gltf.meshes || []).map((m) => m.name);
    const empty = (((gltf.scenes || [])[0] || {}).extras || {}).empty || [];
    const missing = wanted.filter((n) => !names.includes(n) && !empty.includes(n));
    const info = report.info || {};
    console.log(`${file}: ${numErrors} errors, ${numWarnings} warnings, ${numInfos} infos; meshes [${names}]` +
                (empty.length ? `, empty [${empty}]` : '') + `; ${info.totalTriangleCount || 0} triangles`);
    if (numErrors > 0 || missing.length > 0) {
      if (missing.length) console.error(`${file}: missing meshes ${missing}`);
      failed++;
    }
  }
  return failed ? 1 : 0;
}

main().then((code) => process.exit(code), (err) => { console.error(err); process.exit(1); });
