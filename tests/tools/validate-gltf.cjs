// Runs the Khronos glTF-Validator (npm gltf-validator) on one .gltf or .glb file, resolving
// external resources (.bin, images) beside it. Prints the validator's JSON report; exits 0 when it
// has no errors and no warnings, 1 otherwise, 2 when it cannot run.
//   node validate-gltf.cjs VALIDATOR_DIR FILE
'use strict';
const fs = require('fs');
const path = require('path');

const [validatorDir, file] = process.argv.slice(2);
if (!validatorDir || !file) {
    console.error('usage: node validate-gltf.cjs VALIDATOR_DIR FILE');
    process.exit(2);
}
let validator;
try {
    validator = require(path.resolve(validatorDir));
} catch (e) {
    console.error(`validate-gltf: cannot load the validator from ${validatorDir}: ${e}`);
    process.exit(2);
}
const folder = path.dirname(file);
validator
    .validateBytes(new Uint8Array(fs.readFileSync(file)), {
        uri: path.basename(file),
        maxIssues: 100,
        externalResourceFunction: (uri) =>
            new Promise((resolve, reject) => {
                try {
                    resolve(new Uint8Array(fs.readFileSync(path.resolve(folder, decodeURIComponent(uri)))));
                } catch (e) {
                    reject(e.toString());
                }
            }),
    })
    .then((report) => {
        console.log(JSON.stringify(report, null, 2));
        process.exit(report.issues.numErrors + report.issues.numWarnings > 0 ? 1 : 0);
    })
    .catch((e) => {
        console.error(`validate-gltf: ${file}: ${e}`);
        process.exit(2);
    });
