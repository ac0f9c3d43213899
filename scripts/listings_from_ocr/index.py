import csv, re, sys
from table import T
from conv import fname, BOOK
t33 = {}
for ln in range(6270, 6331):
    m = re.match(r'^(\d+)\t(\w+)\t([SF])\t([IVX]+\.\d+)', BOOK[ln - 1])
    if m:
        t33[m.group(2)] = (int(m.group(1)), m.group(4), ln)
# Table 33 spells two names differently
alias = {'DPRFLP': 'DPRFLD', 'DCHRVC': 'DCHRCV'}
rows = []
for lid, name, kind, ranges, note in T:
    key = alias.get(name, name)
    item = t33.get(key)
    rows.append(dict(name=name, listing=lid, kind=kind, file=fname(lid, name, kind),
                     lines=' '.join(f'L{a}-{b}' for a, b in ranges),
                     table33=(f'{item[0]} {item[1]} L{item[2]}' if item else ''),
                     note=note))
assert sum(1 for r in rows if r['table33']) == 59, sum(1 for r in rows if r['table33'])
with open(sys.argv[1], 'w', newline='', encoding='utf-8') as f:
    w = csv.DictWriter(f, fieldnames=list(rows[0]), lineterminator='\n')
    w.writeheader(); w.writerows(rows)
