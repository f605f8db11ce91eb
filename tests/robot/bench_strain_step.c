#include <stdlib.h>
#include <string.h>
#include "core_clock.h"
#include "core_math.h"
#include "cs_test.h"
#include "robot_calibration.h"
#include "robot_strain.h"
#include "rod_test_road.h"
int main(int argc, char** argv){
  int order = argc>1?atoi(argv[1]):2, contact = argc>2?atoi(argv[2]):1;
  csrActuator act; csError err; csr_actuatorPreset(&act,"leg",&err);
  cstTerrain tr = csTestFlatRoad(); cscSoftParams soft = csc_softDefaultParams();
  csrStrainParams par = csr_strainDefaultParams(); par.bend_order = order;
  csrStrainSpec sp; memset(&sp,0,sizeof sp); sp.act=&act; sp.params=&par;
  const double F[9] = {1, 0, 0, 0, 0, -1, 0, 1, 0}; memcpy(sp.frame,F,sizeof F);
  sp.hip[1] = csr_actuatorLength(&act) - 0.3; sp.weightless=1; if(contact){sp.terrain=&tr; sp.soft=&soft;}
  csrStrainModel* m = csr_strainModelCreate(&sp,&err); csrStrainData* d = csr_strainDataCreate(m,&err);
  double Z[36], rho[6], dV[6]={0};
  int N=2000; double t0=csu_wallSeconds();
  for(int i=0;i<N;i++){ if(csr_strainPrepare(m,d,5e-3,Z,rho)) {printf("fail\n");break;} csr_strainFinish(m,d,dV,NULL);}
  double t1=csu_wallSeconds();
  printf("order %d contact %d: n = %d, %d points: %.1f us per leg step\n", order, contact, csr_strainDofs(m), 0, 1e6*(t1-t0)/N);
  return 0;
}
