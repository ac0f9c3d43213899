import re, os, sys
def apply(path, fixes):
    lines = open(path, encoding='utf-8').read().split('\n')
    for fx in fixes:
        kind = fx[0]
        if kind == 'sub':            # ('sub', old, new[, note]) one line, mark inserted before it
            _, old, new, *note = fx
            eol = old.endswith('\n')
            old, new = old.rstrip('\n'), new.rstrip('\n')
            hits = [i for i, l in enumerate(lines) if (l.endswith(old) if eol else old in l) and not l.startswith('C OCR')]
            assert len(hits) == 1, (path, old, hits)
            i = hits[0]
            lines[i] = lines[i][:-len(old)] + new if eol else lines[i].replace(old, new)
            mark = f'C OCR: "{old}" -> "{new}"' + (f' ({note[0]})' if note else '')
            j = i
            while j > 0 and lines[j-1].startswith('C OCR:'):
                j -= 1
            # an OCR correction of an earlier correction: rewrite that pair
            chained = False
            for k in range(j, i):
                pairs = re.findall(r'"([^"]*)" -> "([^"]*)"', lines[k])
                for r, f in pairs:
                    if old in f and not chained:
                        lines[k] = lines[k].replace(f'"{r}" -> "{f}"', f'"{r}" -> "{f.replace(old, new)}"')
                        chained = True
            if chained:
                pass
            elif j < i:          # merge with an OCR line right above
                lines[i-1] += '; ' + mark[7:]
            else:
                lines.insert(i, mark)
        elif kind == 'all':          # ('all', regex, repl) every code line, one mark each
            _, rx, rep = fx
            out = []
            for l in lines:
                if l.startswith('C') and (len(l) == 1 or l[1] == ' '):
                    out.append(l); continue
                found = sorted(set(m.group(0) for m in re.finditer(rx, l)))
                if found:
                    newl = re.sub(rx, rep, l)
                    pairs = ', '.join(f'"{f}" -> "{re.sub(rx, rep, f)}"' for f in found)
                    if out and out[-1].startswith('C OCR:'):
                        out[-1] += '; ' + pairs
                    else:
                        out.append('C OCR: ' + pairs)
                    l = newl
                out.append(l)
            lines = out
        elif kind == 'raw':          # ('raw', old_block, new_block) layout fix, no mark unless given in new
            _, old, new = fx
            s = '\n'.join(lines)
            assert s.count(old) == 1, (path, old, s.count(old))
            lines = s.replace(old, new).split('\n')
        else:
            raise ValueError(kind)
    open(path, 'w', encoding='utf-8').write('\n'.join(lines))
