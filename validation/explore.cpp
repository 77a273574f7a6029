#include "GeometricCount.hpp"
#include "GridMethod.hpp"
#include <chrono>
#include <cstdio>
#include <cstdlib>
using namespace dropletFiber; using namespace dropletFiber::validation;
int main(int argc, char** argv){
  PaperSetting s;
  int streams = argc>1? atoi(argv[1]):100; double n = argc>2? atof(argv[2]):10; int nodes = argc>3?atoi(argv[3]):100;
  double beta = argc>4? atof(argv[4]):0.025; int axis = argc>5? atoi(argv[5]):0; int win = argc>6?atoi(argv[6]):1;
  double inj = argc>7? atof(argv[7]): s.dt; double margin = argc>8? atof(argv[8]):0; double cic = argc>9? atof(argv[9]):0;
  SprayDefinition d; d.streams=streams; d.dropletsPerParcel=n; d.injectionInterval=inj;
  FiberCircle f; 
  SprayStreams sp(d);
  double truth = sp.massPerStep()*2*(f.radius+d.dropletRadius)/(2*d.injectionHalfWidth);
  auto t0=std::chrono::steady_clock::now();
  GridMethod g; g.nodes=nodes; g.kernel.beta=beta; g.window=win; g.margin=margin; g.cloudInCellBelow=cic; if(axis) g.eq9.sampling=Eq9Sampling::Axis;
  GridOutcome o = runGridMethod(s,d,f,g);
  auto t1=std::chrono::steady_clock::now();
  MeanAndError geo = geometricMass(d,f,DropletPlacement::ParcelPoint,1,4);
  MeanAndError spr = geometricMass(d,f,DropletPlacement::Spread,8,8);
  SprayDefinition dj=d; dj.jitter=true;
  MeanAndError fine = geometricMass(dj,f,DropletPlacement::Spread,16,16);
  auto t2=std::chrono::steady_clock::now();
  MeasuredField mf = measureField(sp, s.depth, -d.injectionHalfWidth, d.injectionHalfWidth, 0.01,0.06, 2);
  double formula = formulaCollisionMass(mf.rho, mf.rMeanMass, f, s.depth, Eigen::Vector3d(0,-1,0), s.dt);
  printf("truth %.6e formula %+.5f grid %+.5f (rho %+.5f) geo %+.5f spread %+.5f±%.5f fine %+.5f±%.5f  fallback %ld dep %ld  tgrid %.2fs tgeo %.2fs\n",
   truth, formula/truth-1, o.mass/truth-1, o.rhoAtFiber/sp.analyticDensity(s.depth)-1, geo.mean/truth-1, spr.mean/truth-1, spr.standardError/truth, fine.mean/truth-1, fine.standardError/truth,
   (long)o.parcelsFallback,(long)o.parcelsDeposited,
   std::chrono::duration<double>(t1-t0).count(), std::chrono::duration<double>(t2-t1).count());
}
