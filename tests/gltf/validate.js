// Validates one .gltf or .glb with the Khronos glTF-Validator and prints its report as JSON.
// Usage: node validate.js NODE_MODULES_DIR FILE. Exit 0 when validated (whatever the issues),
// 2 when the validator cannot be loaded or run.
'use strict';
const fs = require('fs');
const path = require('path');

const [modules, file] = process.argv.slice(2);
let validator;
try {
    validator = require(path.join(modules, 'gltf-validator'));
} catch (error) {
    console.error(`gltf-validator is not installed in ${modules} (run scripts/setup.sh): ${error.message}`);
    process.exit(2);
}
const folder = path.dirname(path.resolve(file));
validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
    uri: path.basename(file),
    maxIssues: 0,
    writeTimestamp: false,
    externalResourceFunction: (uri) => fs.promises.readFile(path.resolve(folder, decodeURIComponent(uri)))
        .then((data) => new Uint8Array(data)),
}).then((report) => {
    console.log(JSON.stringify(report, null, 2));
}, (error) => {
    console.error(`gltf-validator failed: ${error}`);
    process.exit(2);
});
