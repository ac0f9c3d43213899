import re, sys, os
from table import T
BOOK = open(os.environ.get('SARKP_BOOK', '/work/shared/seeds/000_eb1ab766384ea773.txt'), encoding='utf-8').read().split('\n')
CYR = dict(zip('АВСЕНКМОРТХаеосрхІ', 'ABCEHKMOPTXaeocpxI'))
HEAD = re.compile(r'^(#+\s*)?(VIII|VII|VI|IV|III|II|V|П|X)(\.\d+)?\.?\s*(?=$|[A-Z])')
warn = []

def split_code_strings(s):
    """yield (is_string, text) pieces; quotes '...' are strings"""
    out, i = [], 0
    j = 0
    while j < len(s):
        if s[j] == "'":
            k = s.find("'", j + 1)
            k = len(s) if k < 0 else k + 1
            out.append((False, s[i:j])); out.append((True, s[j:k])); i = j = k; continue
        m = re.match(r'(?<![\w.])(\d+)H', s[j:]) if (j == 0 or not (s[j-1].isalnum() or s[j-1] == '.')) else None
        if m:
            k = min(len(s), j + m.end() + int(m.group(1)))
            out.append((False, s[i:j])); out.append((True, s[j:k])); i = j = k; continue
        j += 1
    out.append((False, s[i:])); return out

def fix_code(s):
    marks = []
    pieces = split_code_strings(s)
    res = []
    for is_str, t in pieces:
        if is_str:
            res.append(t); continue
        def wr(m):
            new = f'{m.group(1)}({m.group(2)},{m.group(3)})'.replace('Ø', '0').replace('θ', '0')
            marks.append((m.group(0), new)); return new
        t = re.sub(r'\b(WRITE|READ)\s*\(([\dØθ]+)\.\s?([\dØθ]+)\)', wr, t)
        # zeros
        def zero(m):
            w = m.group(0); n = re.sub(r'Ø|θ|∅|\\varnothing|О(?=[\d.])', '0', w)
            if n != w: marks.append((w, n))
            return n
        t = re.sub(r'[\w.\\Øθ∅]*(Ø|θ|∅|\\varnothing)[\w.Øθ∅]*', zero, t)
        # relational operators read with commas or spaced dots
        def rel(m):
            new = '.%s.' % m.group(2)
            if ',' in m.group(0):
                marks.append((m.group(0).strip(), new))
            return new
        t = re.sub(r'\s*([.,])\s*(LT|LE|GT|GE|EQ|NE|AND|OR|NOT)\s*([.,])\s*', lambda m: rel(m) if True else '', t)
        # cyrillic look-alikes in code
        def cyr(m):
            w = m.group(0); n = ''.join(CYR.get(c, c) for c in w)
            if n != w: marks.append((w, n))
            return n
        t = re.sub(r'\w*[А-Яа-яІ]\w*', lambda m: cyr(m) if all(c in CYR or c.isascii() for c in m.group(0)) else m.group(0), t)
        def low(m):
            w = m.group(0); n = w.upper(); marks.append((w, n)); return n
        t = re.sub(r'\b\w*[a-z]\w*\b', low, t)
        def dash(m):
            marks.append((m.group(0), '-')); return '-'
        if not re.search(r'[А-Я]', t):
            t = re.sub(r'[—–]', dash, t)
        def ier(m):
            marks.append(('1ER', 'IER')); return 'IER'
        t = re.sub(r'(?<![\w.])1ER\b', ier, t)
        res.append(t)
    return ''.join(res), marks

def clean(raw):
    s = re.sub(r'\s*\$\\theta\$\s*', 'θ', raw)
    s = re.sub(r'\\text\{([^}]*)\}', r'\1', s)
    s = re.sub(r'\\(cos|sin|tan|sqrt|arccos|ln|exp)\b', lambda m: m.group(1).upper(), s)
    s = s.replace('$', '')
    s = s.replace('\\*', '*').replace('\\_', '_').replace('\\#', '#').replace('\\', '\\')
    s = s.rstrip()
    s = re.sub(r'^#+\s+', '', s.strip())
    s = re.sub(r'^- (?=[СC] )', '', s)
    return s

def convert(lid, name, kind, ranges, note):
    out = []
    first = True
    for a, b in ranges:
        for ln in range(a, b + 1):
          raw = BOOK[ln - 1]
          pending = [clean(raw)]
          while pending:
            s = pending.pop(0)
            if s.startswith('```') or s == '' or s == '---':
                continue
            if first:
                first = False
                m = HEAD.match(s)
                if m:
                    s = s[m.end():].strip()
                    if not s: continue
            # comment line
            if re.match(r'^[СC](\s|$)(?!\s*=)', s) and not re.match(r'^C\s*=', s):
                txt = re.sub(r'^[СC]\s*', '', s)
                txt = re.sub(r'\s+', ' ', txt)
                zm = sorted(set(re.findall(r'\S*[θØ]\S*', txt)))
                if zm:
                    out.append('C OCR: ' + ', '.join(f'"{w}" -> "{w.replace("θ", "0").replace("Ø", "0")}"' for w in zm))
                    txt = txt.replace('θ', '0').replace('Ø', '0')
                # (a merged comment mark; not the preposition of 'С КОТОРОЙ', 'С КАЧАЮЩИМСЯ')
                parts = re.split(r' С (?=[А-ЯA-Z0-9])(?!КОТОРОЙ|КАЧАЮЩИМСЯ)', txt) if len(txt) > 62 else [txt]
                for p in parts:
                    out.append(('C ' + p).rstrip())
                continue
            if len(s) > 66 and (' \\*' in raw or ' С ' in s):
                # OCR joined a statement, its continuations and comments into one line
                segs = re.split(r' (?=\*[A-Z0-9(\'])| (?=С [А-Я])', s)
                if len(segs) > 1:
                    pending.extend(segs[1:]); s = segs[0]
            if re.search(r'[а-я]{3}', s) and "'" not in s and 'H ' not in s:
                warn.append(f'{lid} L{ln} PROSE? {s[:70]}')
            s = re.sub(r'\s+', ' ', s)
            cont = False
            label = ''
            if s.startswith('*'):
                cont = True; s = s[1:].strip()
            else:
                m = re.match(r'^([\dØθ]{1,5})\s+(\S.*)$', s)
                if m and m.group(1)[0].isdigit():
                    label, s = m.group(1), m.group(2)
                    if not label.isdigit():
                        out.append(f'C OCR: "{label}" -> "{label.replace("Ø", "0").replace("θ", "0")}"')
                        label = label.replace('Ø', '0').replace('θ', '0')
            s, marks = fix_code(s)
            for old, new in marks:
                out.append(f'C OCR: "{old}" -> "{new}"')
            if cont:
                line = '     *' + s
            else:
                line = f'{label:<5} ' + s
            if len(line) > 72:
                warn.append(f'{lid} L{ln} >72 ({len(line)})')
            out.append(line.rstrip())
    return out

T33 = {}
for _ln in range(6270, 6331):
    _m = re.match(r'^(\d+)\t(\w+)\t([SF])\t([IVX]+\.\d+)', BOOK[_ln - 1])
    if _m:
        T33[_m.group(2)] = (_m.group(1), _m.group(4))
T33['DPRFLP'] = T33.pop('DPRFLD'); T33['DCHRVC'] = T33.pop('DCHRCV')

def header(lid, name, kind, ranges, note):
    lines = ', '.join(f'L{a}-{b}' for a, b in ranges)
    what = 'PROGRAM' if kind == 'program' else name
    h = [f'C LISTING {lid} {what}: BELOKONEV 1990, BOOK LINES {lines}',
         'C AS PRINTED. OCR MISREADINGS CORRECTED, EACH MARKED "C OCR:".']
    if name in T33 and T33[name][1] != lid:
        h.append(f'C TABLE 33 (L6267-6330) NUMBERS IT {T33[name][1]}.')
    if note:
        h.append(f'C NOTE: {note}')
    return h

def fname(lid, name, kind):
    return f'{lid}_{"program" if kind == "program" else name}.f'

if __name__ == '__main__':
    dest = sys.argv[1]
    only = sys.argv[2:]
    os.makedirs(dest, exist_ok=True)
    for t in T:
        if only and t[1] not in only and t[0] not in only: continue
        body = convert(*t)
        with open(os.path.join(dest, fname(t[0], t[1], t[2])), 'w', encoding='utf-8') as f:
            f.write('\n'.join(header(*t) + body) + '\n')
    print('\n'.join(warn))
