#!/usr/bin/env -S node --no-warnings
// Runs a wasm32-wasip1 program under Node's built-in WASI (node:wasi).
//
//   node scripts/wasi-run.mjs [--dir HOST_DIR]... PROGRAM.wasm [ARGS...]
//
// The current directory is preopened as "." and every --dir is preopened at
// the same path it has on the host, so the program can open files there by
// the same relative or absolute path. The exit code is the program's.
import { readFile } from 'node:fs/promises';
import { resolve } from 'node:path';
import { argv, env, exit } from 'node:process';
import { WASI } from 'node:wasi';

const args = argv.slice(2);
const preopens = { '.': '.' };
while (args.length > 0 && args[0] === '--dir') {
  args.shift();
  const dir = args.shift();
  if (dir === undefined) {
    console.error('wasi-run: --dir needs a directory');
    exit(2);
  }
  preopens[dir] = dir;
  preopens[resolve(dir)] = dir;
}
const program = args[0];
if (program === undefined) {
  console.error('usage: wasi-run.mjs [--dir HOST_DIR]... PROGRAM.wasm [ARGS...]');
  exit(2);
}

const wasi = new WASI({
  version: 'preview1',
  args,
  env,
  preopens,
  returnOnExit: true,
});
let code;
try {
  const module = await WebAssembly.compile(await readFile(program));
  const instance = await WebAssembly.instantiate(module, wasi.getImportObject());
  code = wasi.start(instance);
} catch (error) {
  console.error(`wasi-run: ${program}: ${error && error.stack ? error.stack : error}`);
  code = 101;
}
exit(typeof code === 'number' ? code : 0);
