M_0=30 ;
M0[0]=30 ; N0[0]=30 ;
M0[1]=32 ; N0[1]=28 ;
M0[2]=28 ; N0[2]=30 ;
M0[3]=30 ; N0[3]=32 ;
M0[4]=32 ; N0[4]=26 ;
M0[5]=26 ; N0[5]=32 ;
M0[6]=32 ; N0[6]=32 ;
M0[7]=34 ; N0[7]=28 ;
M0[8]=28 ; N0[8]=34 ;
M0[9]=28 ; N0[9]=28 ;
M0[10]=35 ; N0[10]=30 ;
M0[11]=25 ; N0[11]=35 ;
M0[12]=30 ; N0[12]=25 ;
M0[13]=35 ; N0[13]=25 ;
M0[14]=25 ; N0[14]=30 ;
M0[15]=30 ; N0[15]=35 ;
M1[0]=24 ; N1[0]=30 ;
M1[1]=36 ; N1[1]=24 ;
M1[2]=30 ; N1[2]=36 ;
M1[3]=24 ; N1[3]=31 ;
M1[4]=35 ; N1[4]=24 ;
M1[5]=31 ; N1[5]=35 ;
M1[6]=24 ; N1[6]=32 ;
M1[7]=34 ; N1[7]=24 ;
M1[8]=32 ; N1[8]=34 ;
M1[9]=24 ; N1[9]=33 ;
M1[10]=33 ; N1[10]=24 ;
M1[11]=33 ; N1[11]=33 ;
M1[12]=24 ; N1[12]=34 ;
M1[13]=32 ; N1[13]=24 ;
M1[14]=34 ; N1[14]=32 ;
M1[15]=24 ; N1[15]=35 ;
M1[16]=31 ; N1[16]=24 ;
M1[17]=35 ; N1[17]=31 ;
M1[18]=24 ; N1[18]=36 ;
M1[19]=30 ; N1[19]=24 ;
M1[20]=36 ; N1[20]=30 ;
M1[21]=25 ; N1[21]=29 ;
M1[22]=29 ; N1[22]=36 ;
M1[23]=36 ; N1[23]=25 ;
M1[24]=25 ; N1[24]=31 ;
M1[25]=34 ; N1[25]=25 ;
M1[26]=31 ; N1[26]=34 ;
M1[27]=25 ; N1[27]=32 ;
M1[28]=33 ; N1[28]=25 ;
M1[29]=32 ; N1[29]=33 ;
M1[30]=25 ; N1[30]=33 ;
M1[31]=32 ; N1[31]=25 ;
M1[32]=33 ; N1[32]=32 ;
M1[33]=25 ; N1[33]=34 ;
M1[34]=31 ; N1[34]=25 ;
M1[35]=34 ; N1[35]=31 ;
M1[36]=25 ; N1[36]=36 ;
M1[37]=29 ; N1[37]=25 ;
M1[38]=36 ; N1[38]=29 ;
M1[39]=26 ; N1[39]=28 ;
M1[40]=28 ; N1[40]=36 ;
M1[41]=36 ; N1[41]=26 ;
M1[42]=26 ; N1[42]=29 ;
M1[43]=29 ; N1[43]=35 ;
M1[44]=35 ; N1[44]=26 ;
M1[45]=26 ; N1[45]=30 ;
M1[46]=34 ; N1[46]=26 ;
M1[47]=30 ; N1[47]=34 ;
M1[48]=26 ; N1[48]=31 ;
M1[49]=33 ; N1[49]=26 ;
M1[50]=31 ; N1[50]=33 ;
M1[51]=26 ; N1[51]=33 ;
M1[52]=31 ; N1[52]=26 ;
M1[53]=33 ; N1[53]=31 ;
M1[54]=26 ; N1[54]=34 ;
M1[55]=30 ; N1[55]=26 ;
M1[56]=34 ; N1[56]=30 ;
M1[57]=26 ; N1[57]=35 ;
M1[58]=29 ; N1[58]=26 ;
M1[59]=35 ; N1[59]=29 ;
M1[60]=26 ; N1[60]=36 ;
M1[61]=28 ; N1[61]=26 ;
M1[62]=36 ; N1[62]=28 ;
M1[63]=27 ; N1[63]=27 ;
M1[64]=27 ; N1[64]=36 ;
M1[65]=36 ; N1[65]=27 ;
M1[66]=27 ; N1[66]=28 ;
M1[67]=28 ; N1[67]=35 ;
M1[68]=35 ; N1[68]=27 ;
M1[69]=27 ; N1[69]=29 ;
M1[70]=29 ; N1[70]=34 ;
M1[71]=34 ; N1[71]=27 ;
M1[72]=27 ; N1[72]=30 ;
M1[73]=33 ; N1[73]=27 ;
M1[74]=30 ; N1[74]=33 ;
M1[75]=27 ; N1[75]=31 ;
M1[76]=32 ; N1[76]=27 ;
M1[77]=31 ; N1[77]=32 ;
M1[78]=27 ; N1[78]=32 ;
M1[79]=31 ; N1[79]=27 ;
M1[80]=32 ; N1[80]=31 ;
M1[81]=27 ; N1[81]=33 ;
M1[82]=30 ; N1[82]=27 ;
M1[83]=33 ; N1[83]=30 ;
M1[84]=27 ; N1[84]=34 ;
M1[85]=29 ; N1[85]=27 ;
M1[86]=34 ; N1[86]=29 ;
M1[87]=27 ; N1[87]=35 ;
M1[88]=28 ; N1[88]=27 ;
M1[89]=35 ; N1[89]=28 ;
M1[90]=28 ; N1[90]=29 ;
M1[91]=29 ; N1[91]=33 ;
M1[92]=33 ; N1[92]=28 ;
M1[93]=28 ; N1[93]=31 ;
M1[94]=31 ; N1[94]=28 ;
M1[95]=31 ; N1[95]=31 ;
M1[96]=28 ; N1[96]=32 ;
M1[97]=30 ; N1[97]=28 ;
M1[98]=32 ; N1[98]=30 ;
M1[99]=28 ; N1[99]=33 ;
M1[100]=29 ; N1[100]=28 ;
M1[101]=33 ; N1[101]=29 ;
M1[102]=29 ; N1[102]=29 ;
M1[103]=29 ; N1[103]=32 ;
M1[104]=32 ; N1[104]=29 ;
M1[105]=29 ; N1[105]=30 ;
M1[106]=31 ; N1[106]=29 ;
M1[107]=30 ; N1[107]=31 ;
M1[108]=29 ; N1[108]=31 ;
M1[109]=30 ; N1[109]=29 ;
M2[0]=31 ; N2[0]=30 ;
NbAss_0=16 ;
NbAss_1=110 ;
NbAss_2=1 ;
NbAss_3=0;

ep_ass=206.3 ;
pas_ass=210.3 ;
diam_pnl=206.3 ;

r1=4400 ;
r2=7900 ;
r3=2450 ;
r4=5980 ;
r5=1080 ;
h1b=0 ;
h2=6640 ;
h3=420 ;
h4=4000 ;
h5=1000 ;










//////////////////////////////////
//				//
//	 COEUR TYPE PHX-SFR	//
//				//
//////////////////////////////////

rap1=0.4;
r1=rap1*4400 ;
r2=rap1*7900 ;
r3=1.5*rap1*2450 ;
r4=rap1*5980 ;
r5=rap1*1080 ;


i_mesh = 2;
// 0 : maillage sortie coeur uniquement
// 1 : maillage sortie coeur + collecteur chaud
// 2 : maillage interassemblage uniquement

i_conf = 0;
// Utile si imesh vaut 0 ou 1
// 0 : non conforme aux assemblages & reflecteurs
// 1 : conforme aux assemblages & reflecteurs

itype_PNL = 0;		// geometrie des P.N.L : 0 : hexagonale - 1 : Circulaire - 2 : Octogonale


///////////////////////////////
// paramètres de discrétisation
///////////////////////////////

nbpt_ssbcc = 5;		// nombre de couche entre la sortie coeur et le bcc

lcar  = pas_ass;	// longeur caracteristique associee aux assemblages - reflecteurs - P.N.L.
lcar2 = 3.*lcar;	// longeur caracteristique associee a la partie inferieure de la virole du Collecteur Chaud (en-dessous de l'epaulement)
lcar3 = 8.*lcar;	// longeur caracteristique associee a la partie superieure de la virole du Collecteur Chaud (au-dessus de l'epaulement)

Mesh.Algorithm    = 1;  // 2D mesh algorithm (1=MeshAdapt+Delaunay, 4=MeshAdapt, 5=Delaunay, 6=Frontal)
Mesh.Algorithm3D  = 4;  // 3D mesh algorithm (1=Tetgen+Delaunay, 4=Netgen)
Mesh.OptimizeNetgen = 1;


//**********************************************************
//**********************************************************

x0=0.;
y0=0.;
rac3= 1.732050807568877294;
rac2= 1.414213562373095049;
nbarre=-1;
nbarre_lat=-1;
nassemblage=-1;
nreflecteur=-1;
npnl=-1;
indice0=-1;
indice1=-1;
indice2=-1;
indice3=-1;
indice4=-1;
indice0lat=-1;

barre_lat[ ] = { } ;
ass[ ] = { } ;
refl[] = { } ;
pnl[] = { } ;

lbord0b[ ] = { } ;
lbord0h[ ] = { } ;
lbord[ ] = { } ;
lbord2[ ] = { } ;
lbord3[ ] = { } ;


///////////////////
Function outerLoops
///////////////////
this_point=-1 ;
first_point=-1 ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1033.2,-734.05,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1029.73,-736.05,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-970.179,-839.2,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-851.072,-839.2,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-847.608,-841.2,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-788.054,-944.35,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-668.947,-944.35,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-665.483,-946.35,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-605.929,-1049.5,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-486.822,-1049.5,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-483.358,-1051.5,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,-1154.65,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,-1154.65,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-301.233,-1156.65,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,-1259.8,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,-1259.8,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-119.107,-1261.8,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,-1364.95,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,-1364.95,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {119.107,-1261.8,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,-1259.8,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,-1259.8,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {301.233,-1156.65,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,-1154.65,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,-1154.65,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {483.358,-1051.5,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {486.822,-1049.5,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {605.929,-1049.5,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {665.483,-946.35,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {668.947,-944.35,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {788.054,-944.35,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {847.608,-841.2,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {851.072,-839.2,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {970.179,-839.2,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1029.73,-736.05,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1033.2,-734.05,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,-734.05,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1211.86,-630.9,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,-527.75,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,-523.75,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1211.86,-420.6,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,-317.45,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,-313.45,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1211.86,-210.3,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,-107.15,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,-103.15,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1211.86,0,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,103.15,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,107.15,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1211.86,210.3,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,313.45,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,317.45,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1211.86,420.6,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,523.75,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,527.75,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1211.86,630.9,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,734.05,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1033.2,734.05,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1029.73,736.05,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {970.179,839.2,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {851.072,839.2,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {847.608,841.2,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {788.054,944.35,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {668.947,944.35,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {665.483,946.35,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {605.929,1049.5,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {486.822,1049.5,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {483.358,1051.5,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,1154.65,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,1154.65,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {301.233,1156.65,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,1259.8,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,1259.8,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {119.107,1261.8,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,1364.95,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,1364.95,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-119.107,1261.8,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,1259.8,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,1259.8,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-301.233,1156.65,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,1154.65,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,1154.65,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-483.358,1051.5,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-486.822,1049.5,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-605.929,1049.5,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-665.483,946.35,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-668.947,944.35,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-788.054,944.35,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-847.608,841.2,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-851.072,839.2,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-970.179,839.2,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1029.73,736.05,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1033.2,734.05,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,734.05,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1211.86,630.9,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,527.75,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,523.75,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1211.86,420.6,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,317.45,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,313.45,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1211.86,210.3,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,107.15,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,103.15,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1211.86,0,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,-103.15,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,-107.15,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1211.86,-210.3,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,-313.45,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,-317.45,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1211.86,-420.6,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,-523.75,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,-527.75,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1211.86,-630.9,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,-734.05,0,lcar } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { old_point, this_point } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { this_point, first_point } ;
nassemblage++; lbord[nassemblage]=newreg ;
Line Loop(lbord[nassemblage]) = { c[{indice1-113:indice1 }] } ;

Return
////////////////////
// End outerLoops //
////////////////////


///////////////////
Function innerLoops
///////////////////
lbordia[ ] = { } ;
nbordia=-1;
nlinia=-1;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,-1158.65,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {245.143,-1261.8,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,-1259.8,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {301.233,-1156.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,-1053.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,-1053.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {63.0178,-1156.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,-1259.8,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {119.107,-1261.8,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,-1158.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,-1158.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-119.107,-1261.8,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,-1259.8,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-63.0178,-1156.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,-1053.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,-1053.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-301.233,-1156.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,-1259.8,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-245.143,-1261.8,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,-1158.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,-1158.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,-1154.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,-1154.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-245.143,-1051.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,-948.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,-948.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-483.358,-1051.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-486.822,-1049.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-427.268,-946.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-486.822,-843.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-605.929,-843.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-665.483,-946.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-668.947,-944.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-609.393,-841.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-668.947,-738.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-788.054,-738.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-847.608,-841.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-788.054,-944.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-791.518,-946.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-851.072,-843.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-970.179,-843.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-970.179,-839.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-851.072,-839.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-791.518,-736.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-851.072,-632.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-970.179,-632.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1029.73,-736.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1033.2,-734.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-973.643,-630.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1033.2,-527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,-527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,-523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1033.2,-523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-973.643,-420.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1033.2,-317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,-317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1211.86,-420.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1215.32,-418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1155.77,-315.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1215.32,-212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1211.86,-210.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,-313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1033.2,-313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-973.643,-210.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1033.2,-107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,-107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,-103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1033.2,-103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-973.643,0,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1033.2,103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1033.2,107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-973.643,210.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1033.2,313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1211.86,210.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1215.32,212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1155.77,315.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1215.32,418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1211.86,420.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1033.2,317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-973.643,420.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1033.2,523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1152.3,527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1033.2,527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-973.643,630.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1033.2,734.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1029.73,736.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-970.179,632.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-851.072,632.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-791.518,736.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-851.072,839.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-970.179,839.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-970.179,843.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-851.072,843.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-791.518,946.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-788.054,944.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-847.608,841.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-788.054,738.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-668.947,738.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-609.393,841.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-668.947,944.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-665.483,946.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-605.929,843.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-486.822,843.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-427.268,946.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-486.822,1049.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-483.358,1051.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,948.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,948.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-245.143,1051.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,1154.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,1154.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,1158.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,1158.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-245.143,1261.8,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,1259.8,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-301.233,1156.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,1053.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,1053.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-63.0178,1156.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,1259.8,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-119.107,1261.8,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,1158.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,1158.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {119.107,1261.8,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,1259.8,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {63.0178,1156.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,1053.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,1053.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {301.233,1156.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,1259.8,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {245.143,1261.8,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,1158.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,1158.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,1154.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,1154.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {245.143,1051.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,948.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,948.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {483.358,1051.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {486.822,1049.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {427.268,946.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {486.822,843.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {605.929,843.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {665.483,946.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {668.947,944.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {609.393,841.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {668.947,738.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {788.054,738.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {847.608,841.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {788.054,944.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {791.518,946.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {851.072,843.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {970.179,843.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {970.179,839.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {851.072,839.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {791.518,736.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {851.072,632.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {970.179,632.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1029.73,736.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1033.2,734.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {973.643,630.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1033.2,527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1033.2,523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {973.643,420.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1033.2,317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1211.86,420.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1215.32,418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1155.77,315.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1215.32,212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1211.86,210.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1033.2,313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {973.643,210.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1033.2,107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1033.2,103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {973.643,0,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1033.2,-103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,-103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,-107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1033.2,-107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {973.643,-210.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1033.2,-313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,-313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1211.86,-210.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1215.32,-212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1155.77,-315.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1215.32,-418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1211.86,-420.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,-317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1033.2,-317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {973.643,-420.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1033.2,-523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,-523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1152.3,-527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1033.2,-527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {973.643,-630.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1033.2,-734.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {1029.73,-736.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {970.179,-632.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {851.072,-632.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {791.518,-736.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {851.072,-839.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {970.179,-839.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {970.179,-843.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {851.072,-843.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {791.518,-946.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {788.054,-944.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {847.608,-841.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {788.054,-738.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {668.947,-738.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {609.393,-841.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {668.947,-944.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {665.483,-946.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {605.929,-843.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {486.822,-843.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {427.268,-946.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {486.822,-1049.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {483.358,-1051.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,-948.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,-948.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {245.143,-1051.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,-1154.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,-1154.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,-1158.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
lbordext22=newreg;
Line Loop(lbordext22) = { linia[{nlinia-233:nlinia }] } ;
/*
this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {119.107,0,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-119.107,0,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,-103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,-103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {483.358,-210.3,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,-107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,-107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {245.143,-210.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,-313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,-313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-245.143,-210.3,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,-107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,-107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-483.358,-210.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,-313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,-313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {119.107,420.6,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-119.107,420.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {483.358,-630.9,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,-527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,-527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {245.143,-630.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,-734.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,-734.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-609.393,0,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-668.947,103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-788.054,103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-847.608,0,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-788.054,-103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-668.947,-103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {483.358,630.9,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,734.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,734.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {245.143,630.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {847.608,0,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {788.054,103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {668.947,103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {609.393,0,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {668.947,-103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {788.054,-103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-245.143,630.9,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,734.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,734.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-483.358,630.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-245.143,-630.9,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,-527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,-527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-483.358,-630.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,-734.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,-734.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {1029.73,525.75,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {970.179,628.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {851.072,628.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {791.518,525.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {851.072,422.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {970.179,422.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-791.518,525.75,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-851.072,628.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-970.179,628.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1029.73,525.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-970.179,422.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-851.072,422.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {119.107,-1051.5,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,-948.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,-948.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-119.107,-1051.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,-1154.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,-1154.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {1029.73,-525.75,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {970.179,-422.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {851.072,-422.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {791.518,-525.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {851.072,-628.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {970.179,-628.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-791.518,-525.75,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-851.072,-422.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-970.179,-422.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1029.73,-525.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-970.179,-628.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-851.072,-628.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {119.107,1051.5,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,1154.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,1154.65,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-119.107,1051.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,948.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,948.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-791.518,-315.45,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-851.072,-212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-970.179,-212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1029.73,-315.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-970.179,-418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-851.072,-418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {847.608,-630.9,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {788.054,-527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {668.947,-527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {609.393,-630.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {668.947,-734.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {788.054,-734.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {301.233,946.35,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,1049.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,1049.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {63.0178,946.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,843.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,843.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-791.518,-105.15,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-851.072,-2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-970.179,-2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1029.73,-105.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-970.179,-208.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-851.072,-208.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {665.483,-736.05,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {605.929,-632.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {486.822,-632.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {427.268,-736.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {486.822,-839.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {605.929,-839.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {483.358,841.2,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,944.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,944.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {245.143,841.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,738.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,738.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-791.518,105.15,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-851.072,208.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-970.179,208.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1029.73,105.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-970.179,2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-851.072,2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {483.358,-841.2,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,-738.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,-738.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {245.143,-841.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,-944.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,-944.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {665.483,736.05,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {605.929,839.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {486.822,839.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {427.268,736.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {486.822,632.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {605.929,632.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-791.518,315.45,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-851.072,418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-970.179,418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-1029.73,315.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-970.179,212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-851.072,212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {301.233,-946.35,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,-843.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,-843.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {63.0178,-946.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,-1049.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,-1049.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {847.608,630.9,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {788.054,734.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {668.947,734.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {609.393,630.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {668.947,527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {788.054,527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-609.393,-630.9,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-668.947,-527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-788.054,-527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-847.608,-630.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-788.054,-734.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-668.947,-734.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-63.0178,946.35,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,1049.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,1049.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-301.233,946.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,843.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,843.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {1029.73,-315.45,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {970.179,-212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {851.072,-212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {791.518,-315.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {851.072,-418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {970.179,-418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-609.393,-420.6,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-668.947,-317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-788.054,-317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-847.608,-420.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-788.054,-523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-668.947,-523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {847.608,-420.6,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {788.054,-317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {668.947,-317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {609.393,-420.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {668.947,-523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {788.054,-523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {119.107,841.2,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,944.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,944.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-119.107,841.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,738.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,738.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-609.393,-210.3,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-668.947,-107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-788.054,-107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-847.608,-210.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-788.054,-313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-668.947,-313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {665.483,-525.75,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {605.929,-422.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {486.822,-422.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {427.268,-525.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {486.822,-628.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {605.929,-628.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {301.233,736.05,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,839.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,839.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {63.0178,736.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,632.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,632.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-609.393,210.3,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-668.947,313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-788.054,313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-847.608,210.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-788.054,107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-668.947,107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {301.233,-736.05,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,-632.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,-632.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {63.0178,-736.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,-839.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,-839.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {665.483,525.75,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {605.929,628.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {486.822,628.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {427.268,525.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {486.822,422.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {605.929,422.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-609.393,420.6,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-668.947,523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-788.054,523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-847.608,420.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-788.054,317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-668.947,317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {119.107,-841.2,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,-738.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,-738.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-119.107,-841.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,-944.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,-944.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {847.608,420.6,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {788.054,523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {668.947,523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {609.393,420.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {668.947,317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {788.054,317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-609.393,630.9,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-668.947,734.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-788.054,734.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-847.608,630.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-788.054,527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-668.947,527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-63.0178,-946.35,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,-843.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,-843.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-301.233,-946.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,-1049.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,-1049.5,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {1029.73,315.45,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {970.179,418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {851.072,418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {791.518,315.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {851.072,212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {970.179,212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-427.268,-736.05,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-486.822,-632.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-605.929,-632.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-665.483,-736.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-605.929,-839.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-486.822,-839.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-245.143,841.2,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,944.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,944.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-483.358,841.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,738.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,738.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {1029.73,-105.15,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {970.179,-2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {851.072,-2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {791.518,-105.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {851.072,-208.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {970.179,-208.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-427.268,-525.75,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-486.822,-422.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-605.929,-422.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-665.483,-525.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-605.929,-628.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-486.822,-628.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-63.0178,736.05,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,839.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,839.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-301.233,736.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,632.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,632.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {847.608,-210.3,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {788.054,-107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {668.947,-107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {609.393,-210.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {668.947,-313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {788.054,-313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-427.268,-315.45,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-486.822,-212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-605.929,-212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-665.483,-315.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-605.929,-418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-486.822,-418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {665.483,-315.45,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {605.929,-212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {486.822,-212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {427.268,-315.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {486.822,-418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {605.929,-418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {119.107,630.9,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,734.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,734.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-119.107,630.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-427.268,-105.15,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-486.822,-2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-605.929,-2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-665.483,-105.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-605.929,-208.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-486.822,-208.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {483.358,-420.6,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,-317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,-317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {245.143,-420.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,-523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,-523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {301.233,525.75,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,628.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,628.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {63.0178,525.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,422.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,422.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-427.268,105.15,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-486.822,208.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-605.929,208.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-665.483,105.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-605.929,2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-486.822,2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {301.233,-525.75,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,-422.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,-422.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {63.0178,-525.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,-628.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,-628.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {483.358,420.6,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {245.143,420.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-427.268,315.45,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-486.822,418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-605.929,418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-665.483,315.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-605.929,212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-486.822,212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {119.107,-630.9,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,-527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,-527.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-119.107,-630.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,-734.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,-734.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {665.483,315.45,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {605.929,418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {486.822,418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {427.268,315.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {486.822,212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {605.929,212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-427.268,525.75,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-486.822,628.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-605.929,628.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-665.483,525.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-605.929,422.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-486.822,422.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-63.0178,-736.05,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,-632.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,-632.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-301.233,-736.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,-839.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,-839.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {847.608,210.3,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {788.054,313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {668.947,313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {609.393,210.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {668.947,107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {788.054,107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-427.268,736.05,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-486.822,839.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-605.929,839.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-665.483,736.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-605.929,632.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-486.822,632.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-245.143,-841.2,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,-738.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,-738.05,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-483.358,-841.2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,-944.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,-944.35,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {1029.73,105.15,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {970.179,208.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {851.072,208.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {791.518,105.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {851.072,2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {970.179,2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-245.143,-420.6,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,-317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,-317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-483.358,-420.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,-523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,-523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-63.0178,525.75,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,628.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,628.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-301.233,525.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,422.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,422.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {665.483,-105.15,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {605.929,-2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {486.822,-2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {427.268,-105.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {486.822,-208.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {605.929,-208.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-245.143,0,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-483.358,0,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,-103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,-103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {301.233,-315.45,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,-212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,-212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {63.0178,-315.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,-418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,-418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {301.233,315.45,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {63.0178,315.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-245.143,210.3,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-483.358,210.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {119.107,-420.6,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,-317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,-317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-119.107,-420.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,-523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,-523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {483.358,210.3,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {245.143,210.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-245.143,420.6,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,523.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-483.358,420.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-423.804,317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-304.697,317.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-63.0178,-525.75,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,-422.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,-422.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-301.233,-525.75,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,-628.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,-628.9,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {665.483,105.15,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {605.929,208.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {486.822,208.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {427.268,105.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {486.822,2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {605.929,2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-63.0178,-315.45,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,-212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,-212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-301.233,-315.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,-418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,-418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-63.0178,315.45,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,418.6,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-301.233,315.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,212.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {483.358,0,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {245.143,0,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {304.697,-103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {423.804,-103.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-63.0178,-105.15,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,-2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,-2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-301.233,-105.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,-208.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,-208.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {301.233,-105.15,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,-2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,-2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {63.0178,-105.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,-208.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,-208.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {119.107,210.3,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-119.107,210.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {-63.0178,105.15,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,208.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,208.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-301.233,105.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-241.679,2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-122.571,2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {119.107,-210.3,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,-107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,-107.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-119.107,-210.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {-59.5537,-313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {59.5537,-313.45,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;

this_point=-1;
first_point=-1;
old_point=this_point;
this_point=newp;
Point(this_point) = {301.233,105.15,0,lcar } ;
first_point=this_point ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,208.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,208.3,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {63.0178,105.15,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {122.571,2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
old_point=this_point;
this_point=newp;
Point(this_point) = {241.679,2,0,lcar } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { old_point, this_point } ;
nlinia++; linia[nlinia]=newreg; Line(linia[nlinia]) = { this_point, first_point } ;
nbordia++; lbordia[nbordia]=newreg ;
Line Loop(lbordia[nbordia]) = { linia[{nlinia-5:nlinia }] } ;
*/
Return
////////////////////
// End innerLoops //
////////////////////


/////////////////////
Function assemblage
/////////////////////

pc=newp; Point(pc) = { xc  , yc  , 0., lcar } ;

p1=newp; Point(p1) = { xc+ep_ass/rac3      , yc          , 0., lcar } ;
p2=newp; Point(p2) = { xc+ep_ass/(2.*rac3) , yc+ep_ass/2., 0., lcar } ;
p3=newp; Point(p3) = { xc-ep_ass/(2.*rac3) , yc+ep_ass/2., 0., lcar } ;
p4=newp; Point(p4) = { xc-ep_ass/rac3      , yc          , 0., lcar } ;
p5=newp; Point(p5) = { xc-ep_ass/(2.*rac3) , yc-ep_ass/2., 0., lcar } ;
p6=newp; Point(p6) = { xc+ep_ass/(2.*rac3) , yc-ep_ass/2., 0., lcar } ;

indice1++; c[indice1]=newreg; Line(c[indice1]) = { p1, p2 } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { p2, p3 } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { p3, p4 } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { p4, p5 } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { p5, p6 } ;
indice1++; c[indice1]=newreg; Line(c[indice1]) = { p6, p1 } ;

nassemblage++; lbord[nassemblage]=newreg;
Line Loop(lbord[nassemblage]) = { c[{ indice1-5:indice1 }] } ;
ass[nassemblage]=newreg; Plane Surface(ass[nassemblage]) = { lbord[nassemblage] } ;
Point { pc } In Surface { ass[nassemblage] } ;


Return

//////////////
Function barre
//////////////

pc=newp; Point(pc) = { xc  , yc  , 0., lcar } ;

p1=newp; Point(p1) = { xc+ep_ass/rac3      , yc          , 0., lcar } ;
p2=newp; Point(p2) = { xc+ep_ass/(2.*rac3) , yc+ep_ass/2., 0., lcar } ;
p3=newp; Point(p3) = { xc-ep_ass/(2.*rac3) , yc+ep_ass/2., 0., lcar } ;
p4=newp; Point(p4) = { xc-ep_ass/rac3      , yc          , 0., lcar } ;
p5=newp; Point(p5) = { xc-ep_ass/(2.*rac3) , yc-ep_ass/2., 0., lcar } ;
p6=newp; Point(p6) = { xc+ep_ass/(2.*rac3) , yc-ep_ass/2., 0., lcar } ;

p1h=newp; Point(p1h) = { xc+ep_ass/rac3      , yc          , h3, lcar } ;
p2h=newp; Point(p2h) = { xc+ep_ass/(2.*rac3) , yc+ep_ass/2., h3, lcar } ;
p3h=newp; Point(p3h) = { xc-ep_ass/(2.*rac3) , yc+ep_ass/2., h3, lcar } ;
p4h=newp; Point(p4h) = { xc-ep_ass/rac3      , yc          , h3, lcar } ;
p5h=newp; Point(p5h) = { xc-ep_ass/(2.*rac3) , yc-ep_ass/2., h3, lcar } ;
p6h=newp; Point(p6h) = { xc+ep_ass/(2.*rac3) , yc-ep_ass/2., h3, lcar } ;

indice0++; c0b[indice0]=newreg; Line(c0b[indice0]) = { p1, p2 } ; c0h[indice0]=newreg; Line(c0h[indice0]) = { p1h, p2h } ;
indice0++; c0b[indice0]=newreg; Line(c0b[indice0]) = { p2, p3 } ; c0h[indice0]=newreg; Line(c0h[indice0]) = { p2h, p3h } ;
indice0++; c0b[indice0]=newreg; Line(c0b[indice0]) = { p3, p4 } ; c0h[indice0]=newreg; Line(c0h[indice0]) = { p3h, p4h } ;
indice0++; c0b[indice0]=newreg; Line(c0b[indice0]) = { p4, p5 } ; c0h[indice0]=newreg; Line(c0h[indice0]) = { p4h, p5h } ;
indice0++; c0b[indice0]=newreg; Line(c0b[indice0]) = { p5, p6 } ; c0h[indice0]=newreg; Line(c0h[indice0]) = { p5h, p6h } ;
indice0++; c0b[indice0]=newreg; Line(c0b[indice0]) = { p6, p1 } ; c0h[indice0]=newreg; Line(c0h[indice0]) = { p6h, p1h } ;

l11=newreg; Line(l11) = { p1, p1h } ;
l22=newreg; Line(l22) = { p2, p2h } ;
l33=newreg; Line(l33) = { p3, p3h } ;
l44=newreg; Line(l44) = { p4, p4h } ;
l55=newreg; Line(l55) = { p5, p5h } ;
l66=newreg; Line(l66) = { p6, p6h } ;

Transfinite Line { l11 , l22 , l33 , l44 , l55 , l66 } = nbpt_ssbcc ;

surf_lat1 = newreg; Line Loop(surf_lat1) = { c0b[indice0-5], l22 , -c0h[indice0-5] , -l11 } ;
surf_lat2 = newreg; Line Loop(surf_lat2) = { c0b[indice0-4], l33 , -c0h[indice0-4] , -l22 } ;
surf_lat3 = newreg; Line Loop(surf_lat3) = { c0b[indice0-3], l44 , -c0h[indice0-3] , -l33 } ;
surf_lat4 = newreg; Line Loop(surf_lat4) = { c0b[indice0-2], l55 , -c0h[indice0-2] , -l44 } ;
surf_lat5 = newreg; Line Loop(surf_lat5) = { c0b[indice0-1], l66 , -c0h[indice0-1] , -l55 } ;
surf_lat6 = newreg; Line Loop(surf_lat6) = { c0b[indice0  ], l11 , -c0h[indice0  ] , -l66 } ;

nbarre_lat++ ; barre_lat[nbarre_lat]=newreg; Surface(barre_lat[nbarre_lat]) = { surf_lat1 } ;
nbarre_lat++ ; barre_lat[nbarre_lat]=newreg; Surface(barre_lat[nbarre_lat]) = { surf_lat2 } ;
nbarre_lat++ ; barre_lat[nbarre_lat]=newreg; Surface(barre_lat[nbarre_lat]) = { surf_lat3 } ;
nbarre_lat++ ; barre_lat[nbarre_lat]=newreg; Surface(barre_lat[nbarre_lat]) = { surf_lat4 } ;
nbarre_lat++ ; barre_lat[nbarre_lat]=newreg; Surface(barre_lat[nbarre_lat]) = { surf_lat5 } ;
nbarre_lat++ ; barre_lat[nbarre_lat]=newreg; Surface(barre_lat[nbarre_lat]) = { surf_lat6 } ;

nbarre++;
lbord0b[nbarre]=newreg; Line Loop(lbord0b[nbarre]) = { c0b[{ indice0-5:indice0 }] } ;
lbord0h[nbarre]=newreg; Line Loop(lbord0h[nbarre]) = { c0h[{ indice0-5:indice0 }] } ;
barre[nbarre]=newreg; Plane Surface(barre[nbarre]) = { lbord0b[nbarre] } ;
Point { pc } In Surface { barre[nbarre] } ;


//nassemblage++; lbord[nassemblage]=newreg;
//Line Loop(lbord[nassemblage]) = { c[{ indice1-5:indice1 }] } ;
//ass[nassemblage]=newreg; Plane Surface(ass[nassemblage]) = { lbord[nassemblage] } ;
//Point { pc } In Surface { ass[nassemblage] } ;


Return

/////////////////////
Function reflecteur
/////////////////////

ep_ass2=ep_ass;

pc=newp; Point(pc) = { xc  , yc  , 0., lcar } ;

p1=newp; Point(p1) = { xc+ep_ass2/rac3      , yc          , 0., lcar } ;
p2=newp; Point(p2) = { xc+ep_ass2/(2.*rac3) , yc+ep_ass2/2., 0., lcar } ;
p3=newp; Point(p3) = { xc-ep_ass2/(2.*rac3) , yc+ep_ass2/2., 0., lcar } ;
p4=newp; Point(p4) = { xc-ep_ass2/rac3      , yc          , 0., lcar } ;
p5=newp; Point(p5) = { xc-ep_ass2/(2.*rac3) , yc-ep_ass2/2., 0., lcar } ;
p6=newp; Point(p6) = { xc+ep_ass2/(2.*rac3) , yc-ep_ass2/2., 0., lcar } ;

indice2++; c2[indice2]=newreg; Line(c2[indice2]) = { p1, p2 } ;
indice2++; c2[indice2]=newreg; Line(c2[indice2]) = { p2, p3 } ;
indice2++; c2[indice2]=newreg; Line(c2[indice2]) = { p3, p4 } ;
indice2++; c2[indice2]=newreg; Line(c2[indice2]) = { p4, p5 } ;
indice2++; c2[indice2]=newreg; Line(c2[indice2]) = { p5, p6 } ;
indice2++; c2[indice2]=newreg; Line(c2[indice2]) = { p6, p1 } ;

nreflecteur++; lbord2[nreflecteur]=newreg;
Line Loop(lbord2[nreflecteur]) = { c2[{ indice2-5:indice2 }] } ;
refl[nreflecteur]=newreg; Plane Surface(refl[nreflecteur]) = { lbord2[nreflecteur] } ;
Point { pc } In Surface { refl[nreflecteur] } ;

Return

/////////////////////
Function pnl
/////////////////////


//*********
// Hexagone
//*********


If(itype_PNL==0)

lcar_pnl = lcar;

pc=newp; Point(pc) = { xc  , yc  , 0., lcar_pnl } ;

p1=newp; Point(p1) = { xc+diam_pnl/rac3      , yc            , 0., lcar_pnl } ;
p2=newp; Point(p2) = { xc+diam_pnl/(2.*rac3) , yc+diam_pnl/2., 0., lcar_pnl } ;
p3=newp; Point(p3) = { xc-diam_pnl/(2.*rac3) , yc+diam_pnl/2., 0., lcar_pnl } ;
p4=newp; Point(p4) = { xc-diam_pnl/rac3      , yc            , 0., lcar_pnl } ;
p5=newp; Point(p5) = { xc-diam_pnl/(2.*rac3) , yc-diam_pnl/2., 0., lcar_pnl } ;
p6=newp; Point(p6) = { xc+diam_pnl/(2.*rac3) , yc-diam_pnl/2., 0., lcar_pnl } ;

indice4++; c4[indice4]=newreg; Line(c4[indice4]) = { p1, p2 } ;
indice4++; c4[indice4]=newreg; Line(c4[indice4]) = { p2, p3 } ;
indice4++; c4[indice4]=newreg; Line(c4[indice4]) = { p3, p4 } ;
indice4++; c4[indice4]=newreg; Line(c4[indice4]) = { p4, p5 } ;
indice4++; c4[indice4]=newreg; Line(c4[indice4]) = { p5, p6 } ;
indice4++; c4[indice4]=newreg; Line(c4[indice4]) = { p6, p1 } ;

npnl++; lbord3[npnl]=newreg;
Line Loop(lbord3[npnl]) = { c4[{ indice4-5:indice4 }] } ;
pnl[npnl]=newreg; Plane Surface(pnl[npnl]) = { lbord3[npnl] } ;
Point { pc } In Surface { pnl[npnl] } ;

EndIf


//*******
// Cercle
//*******

If(itype_PNL==1)

lcar_pnl = 0.5*diam_pnl;

pc=newp; Point(pc) = { xc  , yc  , 0., lcar_pnl } ;

p1=newp; Point(p1) = { xc+diam_pnl/2.	, yc,		  0.,	 lcar_pnl } ;
p2=newp; Point(p2) = { xc		, yc+diam_pnl/2., 0.,	 lcar_pnl } ;
p3=newp; Point(p3) = { xc-diam_pnl/2.	, yc,		  0.,	 lcar_pnl } ;
p4=newp; Point(p4) = { xc		, yc-diam_pnl/2., 0.,	 lcar_pnl } ;

indice4++; c4[indice4]=newreg; Circle(c4[indice4]) = { p1, pc, p2 } ;
indice4++; c4[indice4]=newreg; Circle(c4[indice4]) = { p2, pc, p3 } ;
indice4++; c4[indice4]=newreg; Circle(c4[indice4]) = { p3, pc, p4 } ;
indice4++; c4[indice4]=newreg; Circle(c4[indice4]) = { p4, pc, p1 } ;

npnl++; lbord3[npnl]=newreg;
Line Loop(lbord3[npnl]) = { c4[{ indice4-3:indice4 }] } ;
pnl[npnl]=newreg; Plane Surface(pnl[npnl]) = { lbord3[npnl] } ;
Point { pc } In Surface { pnl[npnl] } ;

EndIf


//*********
// Octogone
//*********

If(itype_PNL==2)

lcar_pnl = 0.5*diam_pnl;

pc=newp; Point(pc) = { xc  , yc  , 0., lcar_pnl } ;

p1=newp; Point(p1) = { xc+diam_pnl/2.	     , yc,		  	0.,  lcar_pnl } ;
p2=newp; Point(p2) = { xc+diam_pnl/(2.*rac2) , yc+diam_pnl/(2.*rac2),   0.,  lcar_pnl } ;
p3=newp; Point(p3) = { xc		     , yc+diam_pnl/2.,		0.,  lcar_pnl } ;
p4=newp; Point(p4) = { xc-diam_pnl/(2.*rac2) , yc+diam_pnl/(2.*rac2),   0.,  lcar_pnl } ;
p5=newp; Point(p5) = { xc-diam_pnl/2.	     , yc,		  	0.,  lcar_pnl } ;
p6=newp; Point(p6) = { xc-diam_pnl/(2.*rac2) , yc-diam_pnl/(2.*rac2),   0.,  lcar_pnl } ;
p7=newp; Point(p7) = { xc		     , yc-diam_pnl/2.,		0.,  lcar_pnl } ;
p8=newp; Point(p8) = { xc+diam_pnl/(2.*rac2) , yc-diam_pnl/(2.*rac2),   0.,  lcar_pnl } ;


indice4++; c4[indice4]=newreg; Line(c4[indice4]) = { p1, p2 } ;
indice4++; c4[indice4]=newreg; Line(c4[indice4]) = { p2, p3 } ;
indice4++; c4[indice4]=newreg; Line(c4[indice4]) = { p3, p4 } ;
indice4++; c4[indice4]=newreg; Line(c4[indice4]) = { p4, p5 } ;
indice4++; c4[indice4]=newreg; Line(c4[indice4]) = { p5, p6 } ;
indice4++; c4[indice4]=newreg; Line(c4[indice4]) = { p6, p7 } ;
indice4++; c4[indice4]=newreg; Line(c4[indice4]) = { p7, p8 } ;
indice4++; c4[indice4]=newreg; Line(c4[indice4]) = { p8, p1 } ;


npnl++; lbord3[npnl]=newreg;
Line Loop(lbord3[npnl]) = { c4[{ indice4-7:indice4 }] } ;
pnl[npnl]=newreg; Plane Surface(pnl[npnl]) = { lbord3[npnl] } ;
Point { pc } In Surface { pnl[npnl] } ;

EndIf


Return

////////////////////////
Function pompe_echangeur
////////////////////////

indice3++;

centre4=newp; Point(centre4) = { xc, yc, h1b, lcar2 } ;

p61=newp; Point(p61) = { xc+r5  , yc    , h1b, lcar2 } ;
p62=newp; Point(p62) = { xc     , yc+r5 , h1b, lcar2 } ;
p63=newp; Point(p63) = { xc-r5  , yc    , h1b, lcar2 } ;
p64=newp; Point(p64) = { xc     , yc-r5 , h1b, lcar2 } ;

c61=newreg; Circle(c61) = { p61, centre4, p62 } ;
c62=newreg; Circle(c62) = { p62, centre4, p63 } ;
c63=newreg; Circle(c63) = { p63, centre4, p64 } ;
c64=newreg; Circle(c64) = { p64, centre4, p61 } ;

pompeb[indice3]=newreg; Line Loop(pompeb[indice3]) = { c61 , c62 , c63 , c64  } ;
surf5[indice3] =newreg; Plane Surface(surf5[indice3])  = { pompeb[indice3] } ;

centre5=newp; Point(centre5) = { xc, yc, h1b+h4, lcar2 } ;

p71=newp; Point(p71) = { xc+r5  , yc    , h1b+h4, lcar2 } ;
p72=newp; Point(p72) = { xc     , yc+r5 , h1b+h4, lcar2 } ;
p73=newp; Point(p73) = { xc-r5  , yc    , h1b+h4, lcar2 } ;
p74=newp; Point(p74) = { xc     , yc-r5 , h1b+h4, lcar2 } ;

c71=newreg; Circle(c71) = { p71, centre5, p72 } ;
c72=newreg; Circle(c72) = { p72, centre5, p73 } ;
c73=newreg; Circle(c73) = { p73, centre5, p74 } ;
c74=newreg; Circle(c74) = { p74, centre5, p71 } ;

l9 = newreg; Line(l9)   = { p61 , p71 } ;
l10 = newreg; Line(l10) = { p62 , p72 } ;
l11 = newreg; Line(l11) = { p63 , p73 } ;
l12 = newreg; Line(l12) = { p64 , p74 } ;

surf_lat9 = newreg; Line Loop(surf_lat9)   = { l9 , c71 , -l10 , -c61 } ; sl9[indice3]  = newreg; Surface(sl9[indice3])  = { surf_lat9  } ;
surf_lat10 = newreg; Line Loop(surf_lat10) = { l10, c72 , -l11 , -c62 } ; sl10[indice3] = newreg; Surface(sl10[indice3]) = { surf_lat10 } ;
surf_lat11 = newreg; Line Loop(surf_lat11) = { l11, c73 , -l12 , -c63 } ; sl11[indice3] = newreg; Surface(sl11[indice3]) = { surf_lat11 } ;
surf_lat12 = newreg; Line Loop(surf_lat12) = { l12, c74 , -l9  , -c64 } ; sl12[indice3] = newreg; Surface(sl12[indice3]) = { surf_lat12 } ;


centre6=newp; Point(centre6) = { xc, yc, h1b+h4+h5, lcar2 } ;

p91=newp; Point(p91) = { xc+r5  , yc    , h1b+h4+h5, lcar2 } ;
p92=newp; Point(p92) = { xc     , yc+r5 , h1b+h4+h5, lcar2 } ;
p93=newp; Point(p93) = { xc-r5  , yc    , h1b+h4+h5, lcar2 } ;
p94=newp; Point(p94) = { xc     , yc-r5 , h1b+h4+h5, lcar2 } ;

c91=newreg; Circle(c91) = { p91, centre6, p92 } ;
c92=newreg; Circle(c92) = { p92, centre6, p93 } ;
c93=newreg; Circle(c93) = { p93, centre6, p94 } ;
c94=newreg; Circle(c94) = { p94, centre6, p91 } ;

l9b  = newreg; Line(l9b)  = { p71 , p91 } ;
l10b = newreg; Line(l10b) = { p72 , p92 } ;
l11b = newreg; Line(l11b) = { p73 , p93 } ;
l12b = newreg; Line(l12b) = { p74 , p94 } ;

surf_lat9b = newreg; Line Loop(surf_lat9b)   = { l9b , c91 , -l10b , -c71 } ; sl9b[indice3]  = newreg; Surface(sl9b[indice3])  = { surf_lat9b  } ;
surf_lat10b = newreg; Line Loop(surf_lat10b) = { l10b, c92 , -l11b , -c72 } ; sl10b[indice3] = newreg; Surface(sl10b[indice3]) = { surf_lat10b } ;
surf_lat11b = newreg; Line Loop(surf_lat11b) = { l11b, c93 , -l12b , -c73 } ; sl11b[indice3] = newreg; Surface(sl11b[indice3]) = { surf_lat11b } ;
surf_lat12b = newreg; Line Loop(surf_lat12b) = { l12b, c94 , -l9b  , -c74 } ; sl12b[indice3] = newreg; Surface(sl12b[indice3]) = { surf_lat12b } ;


centre7=newp; Point(centre7) = { xc, yc, h1b+h2, lcar3 } ;

p81=newp; Point(p81) = { xc+r5  , yc    , h1b+h2, lcar3 } ;
p82=newp; Point(p82) = { xc     , yc+r5 , h1b+h2, lcar3 } ;
p83=newp; Point(p83) = { xc-r5  , yc    , h1b+h2, lcar3 } ;
p84=newp; Point(p84) = { xc     , yc-r5 , h1b+h2, lcar3 } ;

c81=newreg; Circle(c81) = { p81, centre7, p82 } ;
c82=newreg; Circle(c82) = { p82, centre7, p83 } ;
c83=newreg; Circle(c83) = { p83, centre7, p84 } ;
c84=newreg; Circle(c84) = { p84, centre7, p81 } ;

pompeh[indice3]=newreg; Line Loop(pompeh[indice3]) = { c81 , c82 , c83 , c84  } ;
surf6[indice3] =newreg; Plane Surface(surf6[indice3])  = { pompeh[indice3] } ;

l13 = newreg; Line(l13) = { p91 , p81 } ;
l14 = newreg; Line(l14) = { p92 , p82 } ;
l15 = newreg; Line(l15) = { p93 , p83 } ;
l16 = newreg; Line(l16) = { p94 , p84 } ;

surf_lat13 = newreg; Line Loop(surf_lat13) = { l13, c81 , -l14 , -c91 } ; sl13[indice3] = newreg; Surface(sl13[indice3]) = { surf_lat13 } ;
surf_lat14 = newreg; Line Loop(surf_lat14) = { l14, c82 , -l15 , -c92 } ; sl14[indice3] = newreg; Surface(sl14[indice3]) = { surf_lat14 } ;
surf_lat15 = newreg; Line Loop(surf_lat15) = { l15, c83 , -l16 , -c93 } ; sl15[indice3] = newreg; Surface(sl15[indice3]) = { surf_lat15 } ;
surf_lat16 = newreg; Line Loop(surf_lat16) = { l16, c84 , -l13 , -c94 } ; sl16[indice3] = newreg; Surface(sl16[indice3]) = { surf_lat16 } ;

Return

/////////////////////////////////////
// Generation des interassemblages //
/////////////////////////////////////

If (i_mesh==2)
  Call innerLoops;
  inter_ass =newreg; Plane Surface(inter_ass)  = { lbordext22 } ;
  Physical Surface("inter_ass") = { inter_ass } ;
EndIf
If (i_mesh!=2)

////////////////////////////////////
// Generation des barres de commande
////////////////////////////////////

  nbbarre=0;
  For k In { 0:NbAss_0-1 }

   i=M0[k]-M_0;
   j=N0[k]-M_0;

   xc = x0+i*0.5*rac3*pas_ass;
   yc = y0+i*0.5*pas_ass+j*pas_ass;

   Call barre;

   nbbarre++;

  EndFor
Printf(" %g barres créés " , nbbarre ) ;

/////////////////////////////
// Generation des assemblages
/////////////////////////////

If (i_conf==1)

 nbass=0;

 For k In { 0:NbAss_1-1 }

   i=M1[k]-M_0;
   j=N1[k]-M_0;

   xc = x0+i*0.5*rac3*pas_ass;
   yc = y0+i*0.5*pas_ass+j*pas_ass;

   Call assemblage;

   nbass++;

 EndFor


Printf(" %g assemblages créés " , nbass ) ;

EndIf

If (i_conf==0)
   Call outerLoops;
   ass[0]=newreg ;
   Plane Surface(ass[0]) = { lbord[], lbord0b[] } ;

EndIf

/////////////////////////////
// Generation des reflecteurs
/////////////////////////////

If (i_conf==1)

   nbrefl=0;

 For k In { 0:NbAss_2-1 }

   i=M2[k]-M_0;
   j=N2[k]-M_0;

   xc = x0+i*0.5*rac3*pas_ass;
   yc = y0+i*0.5*pas_ass+j*pas_ass;

   Call reflecteur;

   nbrefl++;

 EndFor

Printf(" %g reflecteurs créés " , nbrefl ) ;

EndIf

/////////////////////////////
// Generation des P.N.L.
/////////////////////////////

   nbpnl=0;

 For k In { 0:NbAss_3-1 }

   i=M3[k]-M_0;
   j=N3[k]-M_0;

   xc = x0+i*0.5*rac3*pas_ass;
   yc = y0+i*0.5*pas_ass+j*pas_ass;

   Call pnl;

   nbpnl++;

 EndFor

Printf(" %g P.N.L créés " , nbpnl ) ;


//////////////////////////////////////////
// Generation de la cuve primaire (virole)
//////////////////////////////////////////

centre=newp; Point(centre) = { x0, y0, 0., lcar2 } ;

p11=newp; Point(p11) = { x0+r1 , y0    , 0., lcar2 } ;
p12=newp; Point(p12) = { x0    , y0+r1 , 0., lcar2 } ;
p13=newp; Point(p13) = { x0-r1 , y0    , 0., lcar2 } ;
p14=newp; Point(p14) = { x0    , y0-r1 , 0., lcar2 } ;

c11=newreg; Circle(c11) = { p11, centre, p12 } ;
c12=newreg; Circle(c12) = { p12, centre, p13 } ;
c13=newreg; Circle(c13) = { p13, centre, p14 } ;
c14=newreg; Circle(c14) = { p14, centre, p11 } ;

virole=newreg; Line Loop(virole) = { c11 , c12 , c13 , c14  } ;

/////////////////////////////////
// Generation de la partie coeur
/////////////////////////////////


inter_ass =newreg; Plane Surface(inter_ass)  = { virole , lbord0b[] , lbord[], lbord2[], lbord3[] } ;

Physical Surface("inter_ass") = { inter_ass } ;



If (i_mesh==0)

Physical Line ("cuve_primaire_bas")  = { c11 , c12 , c13 , c14  } ;

	      Physical Line ("ass")   = { c[] } ;
If(NbAss_0>0) Physical Line ("barre") = { c0b[] } ; EndIf
If(NbAss_2>0 && i_conf==1) Physical Line ("refl")  = { c2[] } ; EndIf
If(NbAss_3>0) Physical Line ("pnl")   = { c4[] } ; EndIf

EndIf




If (i_mesh==1)

	      Physical Surface("ass") = { ass[] } ;
If(NbAss_0>0) Physical Surface("barre") = { barre_lat[] } ; EndIf
If(NbAss_2>0 && i_conf==1) Physical Surface("refl") = { refl[] } ; EndIf
If(NbAss_3>0) Physical Surface("pnl") = { pnl[] } ; EndIf


/////////////////////////////////
// Génération du collecteur chaud
/////////////////////////////////


//*******************************************************************************
// extension de la cuve primaire jusqu'a l'epaulement collecteur chaud (virole1)
//*******************************************************************************

centreb=newp; Point(centreb) = { x0, y0, h1b, lcar2 } ;

p11b=newp; Point(p11b) = { x0+r1 , y0    , h1b, lcar2 } ;
p12b=newp; Point(p12b) = { x0    , y0+r1 , h1b, lcar2 } ;
p13b=newp; Point(p13b) = { x0-r1 , y0    , h1b, lcar2 } ;
p14b=newp; Point(p14b) = { x0    , y0-r1 , h1b, lcar2 } ;

c11b=newreg; Circle(c11b) = { p11b, centreb, p12b } ;
c12b=newreg; Circle(c12b) = { p12b, centreb, p13b } ;
c13b=newreg; Circle(c13b) = { p13b, centreb, p14b } ;
c14b=newreg; Circle(c14b) = { p14b, centreb, p11b } ;

virole1=newreg; Line Loop(virole1) = { c11b , c12b , c13b , c14b  } ;

//********************************************
// cuve du collecteur chaud (virole2b-virole2h)
//********************************************

p21=newp; Point(p21) = { x0+r2 , y0    , h1b, lcar3 } ;
p22=newp; Point(p22) = { x0    , y0+r2 , h1b, lcar3 } ;
p23=newp; Point(p23) = { x0-r2 , y0    , h1b, lcar3 } ;
p24=newp; Point(p24) = { x0    , y0-r2 , h1b, lcar3 } ;

c21=newreg; Circle(c21) = { p21, centreb, p22 } ;
c22=newreg; Circle(c22) = { p22, centreb, p23 } ;
c23=newreg; Circle(c23) = { p23, centreb, p24 } ;
c24=newreg; Circle(c24) = { p24, centreb, p21 } ;

virole2b=newreg; Line Loop(virole2b) = { c21 , c22 , c23 , c24  } ;

centre3=newp; Point(centre3) = { x0, y0, h2+h1b, lcar3 } ;

p31=newp; Point(p31) = { x0+r2 , y0    , h2+h1b, lcar3 } ;
p32=newp; Point(p32) = { x0    , y0+r2 , h2+h1b, lcar3 } ;
p33=newp; Point(p33) = { x0-r2 , y0    , h2+h1b, lcar3 } ;
p34=newp; Point(p34) = { x0    , y0-r2 , h2+h1b, lcar3 } ;

c31=newreg; Circle(c31) = { p31, centre3, p32 } ;
c32=newreg; Circle(c32) = { p32, centre3, p33 } ;
c33=newreg; Circle(c33) = { p33, centre3, p34 } ;
c34=newreg; Circle(c34) = { p34, centre3, p31 } ;

virole2h=newreg; Line Loop(virole2h) = { c31 , c32 , c33 , c34  } ;


//********************************************
// Generation du bcc (bccb-bcch)
//********************************************

centre2=newp; Point(centre2) = { x0, y0, h3, lcar } ;

p41=newp; Point(p41) = { x0+r3  , y0    , h3, lcar } ;
p42=newp; Point(p42) = { x0     , y0+r3 , h3, lcar } ;
p43=newp; Point(p43) = { x0-r3  , y0    , h3, lcar } ;
p44=newp; Point(p44) = { x0     , y0-r3 , h3, lcar } ;

c41=newreg; Circle(c41) = { p41, centre2, p42 } ;
c42=newreg; Circle(c42) = { p42, centre2, p43 } ;
c43=newreg; Circle(c43) = { p43, centre2, p44 } ;
c44=newreg; Circle(c44) = { p44, centre2, p41 } ;

bccb=newreg; Line Loop(bccb) = { c41 , c42 , c43 , c44  } ;

p51=newp; Point(p51) = { x0+r3  , y0     , h2+h1b, lcar3 } ;
p52=newp; Point(p52) = { x0     , y0+r3  , h2+h1b, lcar3 } ;
p53=newp; Point(p53) = { x0-r3  , y0     , h2+h1b, lcar3 } ;
p54=newp; Point(p54) = { x0     , y0-r3  , h2+h1b, lcar3 } ;

c51=newreg; Circle(c51) = { p51, centre3, p52 } ;
c52=newreg; Circle(c52) = { p52, centre3, p53 } ;
c53=newreg; Circle(c53) = { p53, centre3, p54 } ;
c54=newreg; Circle(c54) = { p54, centre3, p51 } ;

bcch=newreg; Line Loop(bcch) = { c51 , c52 , c53 , c54  } ;


//********************************************
// Generation des 6 echangeurs et des 3 pompes
//********************************************

For i In { 0:2 }  // Pompes

  xc = (x0+r4)*Cos(i*2*Pi/3);
  yc = (y0+r4)*Sin(i*2*Pi/3);

Call pompe_echangeur ;

EndFor


alpha = Pi/6;

For i In { 0:2 }  // Echangeurs_gauche

  xc = (x0+r4)*Cos(i*2*Pi/3+alpha);
  yc = (y0+r4)*Sin(i*2*Pi/3+alpha);

Call pompe_echangeur ;

EndFor

For i In { 0:2 }  // Echangeurs_droite

  xc = (x0+r4)*Cos(i*2*Pi/3-alpha);
  yc = (y0+r4)*Sin(i*2*Pi/3-alpha);

Call pompe_echangeur ;

EndFor


///////////////////////////////////////////////////////
// Generation des surfaces et des volumes du collecteur
///////////////////////////////////////////////////////

l1 = newreg; Line(l1) = { p21 , p31 } ;  l5 = newreg; Line(l5) = { p41 , p51 } ;
l2 = newreg; Line(l2) = { p22 , p32 } ;  l6 = newreg; Line(l6) = { p42 , p52 } ;
l3 = newreg; Line(l3) = { p23 , p33 } ;  l7 = newreg; Line(l7) = { p43 , p53 } ;
l4 = newreg; Line(l4) = { p24 , p34 } ;  l8 = newreg; Line(l8) = { p44 , p54 } ;

l1b = newreg; Line(l1b) = { p11 , p11b } ;
l2b = newreg; Line(l2b) = { p12 , p12b } ;
l3b = newreg; Line(l3b) = { p13 , p13b } ;
l4b = newreg; Line(l4b) = { p14 , p14b } ;

surf_lat1 = newreg; Line Loop(surf_lat1) = { l1, c31 , -l2 , -c21 } ; sl1 = newreg; Surface(sl1) = { surf_lat1 } ;
surf_lat2 = newreg; Line Loop(surf_lat2) = { l2, c32 , -l3 , -c22 } ; sl2 = newreg; Surface(sl2) = { surf_lat2 } ;
surf_lat3 = newreg; Line Loop(surf_lat3) = { l3, c33 , -l4 , -c23 } ; sl3 = newreg; Surface(sl3) = { surf_lat3 } ;
surf_lat4 = newreg; Line Loop(surf_lat4) = { l4, c34 , -l1 , -c24 } ; sl4 = newreg; Surface(sl4) = { surf_lat4 } ;

If(h1b>0.)
surf_lat1b = newreg; Line Loop(surf_lat1b) = { l1b, c11b , -l2b , -c11 } ; sl1b = newreg; Surface(sl1b) = { surf_lat1b } ;
surf_lat2b = newreg; Line Loop(surf_lat2b) = { l2b, c12b , -l3b , -c12 } ; sl2b = newreg; Surface(sl2b) = { surf_lat2b } ;
surf_lat3b = newreg; Line Loop(surf_lat3b) = { l3b, c13b , -l4b , -c13 } ; sl3b = newreg; Surface(sl3b) = { surf_lat3b } ;
surf_lat4b = newreg; Line Loop(surf_lat4b) = { l4b, c14b , -l1b , -c14 } ; sl4b = newreg; Surface(sl4b) = { surf_lat4b } ;
EndIf

surf_lat5 = newreg; Line Loop(surf_lat5) = { l5, c51 , -l6 , -c41 } ; sl5 = newreg; Surface(sl5) = { surf_lat5 } ;
surf_lat6 = newreg; Line Loop(surf_lat6) = { l6, c52 , -l7 , -c42 } ; sl6 = newreg; Surface(sl6) = { surf_lat6 } ;
surf_lat7 = newreg; Line Loop(surf_lat7) = { l7, c53 , -l8 , -c43 } ; sl7 = newreg; Surface(sl7) = { surf_lat7 } ;
surf_lat8 = newreg; Line Loop(surf_lat8) = { l8, c54 , -l5 , -c44 } ; sl8 = newreg; Surface(sl8) = { surf_lat8 } ;

If(h1b>0.)
surf1 =newreg; Plane Surface(surf1)  = { virole2b , pompeb[], virole1 } ;
EndIf
If(h1b==0.)
surf1 =newreg; Plane Surface(surf1)  = { virole2b , pompeb[], virole } ;
EndIf
surf3 =newreg; Plane Surface(surf3)  = { virole2h , pompeh[], bcch } ;
surf4 =newreg; Plane Surface(surf4)  = { bccb , lbord0h[] } ;

collecteur[0] = newreg ;


If(h1b==0.)
Surface Loop(collecteur[0]) = { surf1, surf3, surf4, inter_ass,
 				barre_lat[], ass[], refl[], pnl[],
				sl1, sl2, sl3, sl4, sl5, sl6, sl7, sl8 ,
				sl9[], sl10[], sl11[], sl12[],
				sl9b[], sl10b[], sl11b[], sl12b[],
				sl13[], sl14[],	sl15[], sl16[]  } ;
EndIf

If(h1b>0.)
Surface Loop(collecteur[0]) = { surf1, surf3, surf4, inter_ass,
 				barre_lat[], ass[], refl[], pnl[],
				sl1, sl2, sl3, sl4, sl1b, sl2b, sl3b, sl4b, sl5, sl6, sl7, sl8 ,
				sl9[], sl10[], sl11[], sl12[],
				sl9b[], sl10b[], sl11b[], sl12b[],
				sl13[], sl14[],	sl15[], sl16[]  } ;
EndIf

vol = newreg ; Volume(vol) = { collecteur[] } ;


Physical Surface("surf") = { surf1, surf3, surf4,
			     sl1, sl2, sl3, sl4, sl5, sl6, sl7, sl8,
			     sl9[], sl10[], sl11[], sl12[],
			     sl9b[ { 0:2 } ], sl10b[ { 0:2 } ], sl11b[ { 0:2 } ], sl12b[ { 0:2 } ],
			     sl13[], sl14[], sl15[], sl16[]  } ;

If(h1b>0.)
Physical Surface("cuve_primaire_bas") = { sl1b, sl2b, sl3b, sl4b } ;
EndIf

Physical Surface("echg1") = { sl9b[ { 3,6 } ], sl10b[ { 3,6 } ], sl11b[ { 3,6 } ], sl12b[ { 3,6 } ]  } ;
Physical Surface("echg2") = { sl9b[ { 4,7 } ], sl10b[ { 4,7 } ], sl11b[ { 4,7 } ], sl12b[ { 4,7 } ]  } ;
Physical Surface("echg3") = { sl9b[ { 5,8 } ], sl10b[ { 5,8 } ], sl11b[ { 5,8 } ], sl12b[ { 5,8 } ]  } ;

Physical Volume("dom") = { vol } ;

EndIf

EndIf
