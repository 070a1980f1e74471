// A tiny assertion log: every check prints one line; the process exits 1 when one failed.
let failed = 0, passed = 0;

export function check(ok, what, detail = '') {
  if (ok) ++passed;
  else ++failed;
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}${detail ? ` (${detail})` : ''}`);
}

export function summary() {
  console.log(`browser tests: ${passed} passed, ${failed} failed`);
  return failed === 0 ? 0 : 1;
}
