import sys, struct, re
import xml.etree.ElementTree as ET
NS='{http://www.collada.org/2005/11/COLLADASchema}'
def mat(text):
    v=[float(x) for x in text.split()]
    return [v[0:4],v[4:8],v[8:12],v[12:16]]
def mul(a,b): return [[sum(a[i][k]*b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]
def apply(m,p): return [m[i][0]*p[0]+m[i][1]*p[1]+m[i][2]*p[2]+m[i][3] for i in range(3)]
def convert(src, dst, offset):
    root=ET.parse(src).getroot()
    unit=root.find(f'{NS}asset/{NS}unit'); scale=float(unit.get('meter')) if unit is not None else 1.0
    up=root.find(f'{NS}asset/{NS}up_axis').text
    assert up=='Z_UP', up
    geoms={}
    for g in root.iter(f'{NS}geometry'):
        mesh=g.find(f'{NS}mesh'); srcs={}
        for s in mesh.findall(f'{NS}source'):
            fa=s.find(f'{NS}float_array'); srcs['#'+s.get('id')]=[float(x) for x in fa.text.split()]
        verts={}
        for v in mesh.findall(f'{NS}vertices'):
            verts['#'+v.get('id')]=srcs[v.find(f'{NS}input[@semantic="POSITION"]').get('source')]
        tris=[]
        for prim in list(mesh.findall(f'{NS}triangles'))+list(mesh.findall(f'{NS}polylist')):
            inputs=prim.findall(f'{NS}input'); stride=max(int(i.get('offset')) for i in inputs)+1
            vin=[i for i in inputs if i.get('semantic')=='VERTEX'][0]; voff=int(vin.get('offset')); pos=verts[vin.get('source')]
            p=[int(x) for x in prim.find(f'{NS}p').text.split()]
            idx=[p[i+voff] for i in range(0,len(p),stride)]
            if prim.tag.endswith('polylist'):
                vc=[int(x) for x in prim.find(f'{NS}vcount').text.split()]; k=0
                for n in vc:
                    poly=idx[k:k+n]; k+=n
                    for j in range(1,n-1): tris.append((poly[0],poly[j],poly[j+1]))
            else:
                for i in range(0,len(idx),3): tris.append(tuple(idx[i:i+3]))
            geoms['#'+g.get('id')]=(pos,tris) if '#'+g.get('id') not in geoms else (pos, geoms['#'+g.get('id')][1]+tris)
    out=[]
    def walk(node, m):
        mm=m
        for t in node:
            if t.tag==f'{NS}matrix': mm=mul(mm,mat(t.text))
            elif t.tag==f'{NS}translate':
                x,y,z=[float(a) for a in t.text.split()]; mm=mul(mm,[[1,0,0,x],[0,1,0,y],[0,0,1,z],[0,0,0,1]])
        for ig in node.findall(f'{NS}instance_geometry'):
            pos,tris=geoms[ig.get('url')]
            for a,b,c in tris:
                out.append([apply(mm,pos[3*i:3*i+3]) for i in (a,b,c)])
        for ch in node.findall(f'{NS}node'): walk(ch, mm)
    I=[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]
    for vs in root.iter(f'{NS}visual_scene'):
        for n in vs.findall(f'{NS}node'): walk(n, I)
    with open(dst,'wb') as f:
        f.write(b'robopro: from ros-industrial abb_irb2400_support (Apache-2.0)'.ljust(80,b' '))
        f.write(struct.pack('<I',len(out)))
        lo=[1e9]*3; hi=[-1e9]*3
        for t in out:
            f.write(struct.pack('<3f',0,0,0))
            for v in t:
                p=[v[i]*scale+offset[i] for i in range(3)]
                for i in range(3): lo[i]=min(lo[i],p[i]); hi[i]=max(hi[i],p[i])
                f.write(struct.pack('<3f',*p))
            f.write(b'\0\0')
    print(dst, len(out), 'triangles, bbox', [round(x,3) for x in lo], [round(x,3) for x in hi])
off={'base_link':(0,0,0),'link_1':(0,0,0),'link_2':(0.1,0,0.615),'link_3':(0.1,0,1.32),'link_4':(0.358,0,1.455),'link_5':(0.855,0,1.455),'link_6':(0.94,0,1.455)}
for k,o in off.items(): convert(f'/tmp/gui-mesh/{k}.dae', f'/tmp/gui-mesh/{k}.stl', o)
