import h5py, numpy as np
def track(p):
    f=h5py.File(p,'r'); t=f['time'][:]; s=f['support']
    k=[k for k in s.keys()]
    pos=s['position'][:] if 'position' in s else None
    return t,pos,k
t1,p1,k1=track('/work/rom_data/romflat2/run/rom_flat.h5')
t2,p2,k2=track('/work/rom_data/romflat2/rod_flat_2s.h5')
print(k1)
for T in [0.25,0.5,0.75,1.0,1.25,1.5,2.0]:
    if T>t1[-1]+1e-9: break
    i=np.argmin(abs(t1-T)); j=np.argmin(abs(t2-T))
    print(T, t1[i], np.round(p1[i],2), np.round(p2[j],2), 'd', round(float(np.linalg.norm(p1[i]-p2[j])),2))
print('last t', t1[-1])
