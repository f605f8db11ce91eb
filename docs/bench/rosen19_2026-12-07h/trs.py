import collections,sys
def name(i):
    return 'sup_x' if i<3 else 'sup_v' if i<6 else 'sup_w' if i<9 else 'foot%s'%'ABCDEFGH'[(i-9)//3]
for f in sys.argv[1:]:
    L=[l.split() for l in open(f)]
    L=[l for l in L if 1.0<float(l[0])<=2.0]
    acc=[l for l in L if l[3]=='1']; rej=[l for l in L if l[3]=='0']
    hs=sorted(float(l[1]) for l in acc)
    cn=collections.Counter(name(int(l[5])) for l in acc)
    cr=collections.Counter(name(int(l[5])) for l in rej)
    print(f, 'acc',len(acc),'rej',len(rej),'median h %.3g'%hs[len(hs)//2], 'second', sum(l[4]=='1' for l in acc), 'acc by', cn.most_common(5), 'rej by', cr.most_common(4))
