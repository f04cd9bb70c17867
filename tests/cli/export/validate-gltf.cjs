// Runs the Khronos glTF validator (npm gltf-validator) on a .gltf and its external files.
// Prints the report; exits 1 on any error or warning, 2 if the validator cannot be loaded.
'use strict';
const fs = require('fs');
const path = require('path');

let validator;
try {
    validator = require('gltf-validator');
} catch (e) {
    console.error('error: the npm package gltf-validator is not installed (./setup.sh installs it)');
    process.exit(2);
}
const file = process.argv[2];
const folder = path.dirname(file);
validator
    .validateBytes(new Uint8Array(fs.readFileSync(file)), {
        uri: path.basename(file),
        externalResourceFunction: (uri) =>
            new Promise((resolve, reject) => {
                fs.readFile(path.join(folder, decodeURIComponent(uri)), (err, data) =>
                    err ? reject(err.toString()) : resolve(new Uint8Array(data)));
            }),
    })
    .then((report) => {
        const issues = report.issues;
        console.log(`${report.validatorVersion}: ${issues.numErrors} errors, ` +
                    `${issues.numWarnings} warnings, ${issues.numInfos} infos, ${issues.numHints} hints`);
        const severity = ['error', 'warning', 'info', 'hint'];
        for (const m of issues.messages)
            console.log(`  ${severity[m.severity]} ${m.code} ${m.pointer || ''}: ${m.message}`);
        process.exit(issues.numErrors === 0 && issues.numWarnings === 0 ? 0 : 1);
    })
    .catch((error) => {
        console.error(`error: ${error}`);
        process.exit(1);
    });
