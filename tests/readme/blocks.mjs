// The fenced code blocks of a Markdown file (the README and the guides in docs/), with what the README test does with
// each, and the output a block promises through `// prints: <text>` comments.

// Language tag -> what the test does with the block. A block with another (or no) tag fails the test, so that a new
// kind of example cannot slip in unchecked.
export const KINDS = {
  js: 'run', javascript: 'run', mjs: 'run', cjs: 'run',
  ts: 'typecheck', typescript: 'typecheck',
  cpp: 'native', 'c++': 'native',
  cmake: 'cmake',
  // Not run: shell commands install or build (they would modify the machine), HTML needs a page and a server.
  bash: 'not run', sh: 'not run', shell: 'not run', html: 'not run',
};

// [{ file, lang, code, line (1-based line of the opening fence), section (nearest heading above) }]
export function fencedBlocks(markdown, file = 'README.md') {
  const lines = markdown.split('\n');
  const blocks = [];
  let section = '', open = null;
  lines.forEach((text, i) => {
    if (open) {
      if (/^\s*```\s*$/.test(text)) { blocks.push({ ...open, code: open.body.join('\n') + '\n' }); open = null; }
      else open.body.push(text.slice(Math.min(open.indent, text.search(/\S|$/))));
      return;
    }
    const heading = /^#{1,6}\s+(.*)$/.exec(text);
    if (heading) section = heading[1].trim();
    const fence = /^(\s*)```\s*([\w+-]*)\s*$/.exec(text);
    if (fence) open = { file, lang: fence[2].toLowerCase(), line: i + 1, section, indent: fence[1].length, body: [] };
  });
  if (open) throw new Error(`${file} line ${open.line}: code block never closed`);
  return blocks.map(({ body, indent, ...b }) => b);
}

// The texts a block says it prints, in order: every `// prints: <text>` comment (at the end of a line or alone).
export function promisedOutput(code) {
  return [...code.matchAll(/\/\/ prints: (.*)$/gm)].map((m) => m[1].trim());
}

// Each promised text must appear in the output, after the one before it.
export function missingOutput(stdout, promised) {
  let from = 0;
  for (const text of promised) {
    const at = stdout.indexOf(text, from);
    if (at < 0) return text;
    from = at + text.length;
  }
  return null;
}

// A ```bash block made only of `npx rtl ...` lines (text after ` #` is a comment) is the command-line example: the
// README test runs each line with the installed package's `rtl` command. [{ args, output (the `> file`, or null) }],
// or null for any other block (install and build commands stay unrun).
export function cliCommands(code) {
  const lines = code.split('\n').map((l) => l.replace(/\s+#.*$/, '').trim()).filter(Boolean);
  if (!lines.length || !lines.every((l) => /^npx rtl\s/.test(l))) return null;
  return lines.map((l) => {
    const [command, output = null] = l.split(/\s*>\s*/);
    return { args: command.split(/\s+/).slice(2), output };
  });
}

export const isCommonJs = (code) => /^\s*\/\/ CommonJS\b/.test(code);
export const label = (b) => `${b.file} line ${b.line} (${b.section}): \`\`\`${b.lang}`;
