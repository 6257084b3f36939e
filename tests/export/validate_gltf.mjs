// The Khronos glTF validator (npm gltf-validator, web/node_modules) over the
// files named on the command line: prints each file's counts and every
// error and warning, and exits 1 when any file has an error or a warning
// (infos and hints are counted, not failed). A .gltf's buffers are read from
// beside it.
//   node tests/export/validate_gltf.mjs FILE.glb [FILE.gltf ...]
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import { createRequire } from 'node:module';

const require = createRequire(import.meta.url);
const here = path.dirname(new URL(import.meta.url).pathname);
const validator = require(path.join(here, '..', '..', 'web', 'node_modules', 'gltf-validator'));

let failed = false;
for (const file of process.argv.slice(2)) {
  const report = await validator.validateBytes(new Uint8Array(await readFile(file)), {
    uri: path.basename(file),
    maxIssues: 0,
    externalResourceFunction: (uri) =>
      readFile(path.join(path.dirname(file), decodeURIComponent(uri))).then((b) => new Uint8Array(b)),
  });
  const i = report.issues;
  console.log(`${file}: ${i.numErrors} errors, ${i.numWarnings} warnings, ${i.numInfos} infos, ${i.numHints} hints`);
  for (const m of i.messages)
    if (m.severity <= 1)
      console.log(`  ${m.severity === 0 ? 'error' : 'warning'} ${m.code} at ${m.pointer ?? ''}: ${m.message}`);
  if (i.numErrors > 0 || i.numWarnings > 0) failed = true;
}
process.exit(failed ? 1 : 0);
