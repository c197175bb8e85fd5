#!/usr/bin/env node
// Validates an OpenAPI 3 document with @apidevtools/swagger-parser: the document against the
// official OpenAPI 3.0/3.1 JSON schema, then every $ref resolved (local and relative files).
// Usage: node validate.js PATH/openapi.json   (exit 0: valid; 1: invalid, messages on stderr)
'use strict';
const SwaggerParser = require('@apidevtools/swagger-parser');

async function main() {
  const file = process.argv[2];
  if (!file) {
    console.error('usage: node validate.js OPENAPI.json');
    return 2;
  }
  try {
    const api = await SwaggerParser.validate(file);
    const operations = Object.values(api.paths || {})
      .reduce((n, item) => n + Object.keys(item).filter((k) => k !== 'parameters').length, 0);
    console.log(`${file}: valid OpenAPI ${api.openapi}, ${Object.keys(api.paths || {}).length} paths, ${operations} operations`);
    return 0;
  } catch (err) {
    console.error(`${file}: INVALID`);
    console.error(err.message);
    return 1;
  }
}

main().then((code) => process.exit(code));
