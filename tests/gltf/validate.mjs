// The Khronos glTF Validator (npm gltf-validator) on each .glb given: prints its counts and any
// message, and exits 1 if any file has an error or a warning (infos and hints are printed only).
//   usage: node validate.mjs FILE.glb...
import fs from 'node:fs';
import validator from 'gltf-validator';

let failed = false;
for (const file of process.argv.slice(2)) {
  const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
    maxIssues: 50,
  });
  const { numErrors, numWarnings, numInfos, numHints, messages } = report.issues;
  console.log(`${file}: ${numErrors} errors, ${numWarnings} warnings, ${numInfos} infos, ` +
              `${numHints} hints`);
  for (const m of messages) console.log(`  ${m.code} (severity ${m.severity}) ${m.pointer ?? ''}: ${m.message}`);
  if (numErrors > 0 || numWarnings > 0) failed = true;
}
process.exit(failed ? 1 : 0);
