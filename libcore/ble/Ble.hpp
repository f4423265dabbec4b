// hvi::ble: ballistic limit equations for MMOD shields. Include this one header.
//
// Units everywhere in hvi::ble: cm, g/cm^3, km/s, ksi (yield), g (mass), g/cm^2 (areal
// density), degrees from the normal (angles). Convert at the file boundary with
// core/Units.hpp (mmToCm, mpaToKsi, ...). Non-physical arguments throw std::invalid_argument;
// validity limits never throw, they come back as ValidityWarning{code, message}.
//
// API for tools (every performance call returns CriticalDiameterResult{criticalDiameterCm,
// regime, warnings}; regimeName(regime) gives "ballistic" / "shatter" / "hypervelocity"):
//
//   Whipple (WhippleNno.hpp, WhippleDesign.hpp)
//     CriticalDiameterResult whippleNnoCriticalDiameter(const WhippleShield&, const Threat&,
//                                                       NnoShatterConstants = Continuous);
//     Regime whippleNnoRegime(double normalVelocityKmS);
//     WhippleDesign designWhipple(const Threat&, const WhippleDesignInput&,
//                                 YieldRatioConvention = Handbook);
//     double whippleDesignBumperCm(const Threat&, double bumperDensityGCm3, double standoffCm);
//     double whippleDesignRearWallCm(const Threat&, double bumperDensityGCm3,
//                                    double rearWallYieldKsi, double standoffCm,
//                                    YieldRatioConvention = Handbook);
//     double whippleBumperCoefficient(double standoffCm, double diameterCm);
//     double sphereMassG(double diameterCm, double densityGCm3);
//   Single wall (SingleWall.hpp)
//     double semiInfinitePenetrationCm(const Threat&, const SingleWallTarget&);
//     double singleWallRequiredThicknessCm(const Threat&, const SingleWallTarget&,
//                                          SingleWallFailure = DetachedSpall);
//     CriticalDiameterResult singleWallCriticalDiameter(const SingleWallTarget&, const Threat&,
//                                                       SingleWallFailure = DetachedSpall);
//   Honeycomb sandwich (HoneycombSandwich.hpp)
//     CriticalDiameterResult srlCriticalDiameter(const HoneycombSandwichPanel&, const Threat&,
//                                                const SrlParameters& = {});
//     double srlFacesheetDesignCm(const Threat&, double facesheetDensityGCm3,
//                                 double rearFacesheetYieldKsi, double coreThicknessCm,
//                                 const SrlParameters& = {});
//     CriticalDiameterResult honeycombHandbookCriticalDiameter(const HoneycombSandwichPanel&,
//                                                              const Threat&);
//     WhippleShield honeycombEquivalentWhipple(const HoneycombSandwichPanel&);
//   Foam sandwich (FoamSandwich.hpp)
//     CriticalDiameterResult foamSandwichCriticalDiameter(const FoamSandwichPanel&,
//                                                         const Threat&,
//                                                         const FoamSandwichOptions& = {});
//   Stuffed Whipple (StuffedWhipple.hpp)
//     CriticalDiameterResult stuffedWhippleCriticalDiameter(const StuffedWhippleShield&,
//                                                           const Threat&);
//     StuffedWhippleDesign designStuffedWhipple(const Threat&, const StuffedWhippleDesignInput&);
//     double stuffedWhippleRearWallCm(const Threat&, double bumperArealDensityGCm2,
//                                     double stuffingArealDensityGCm2,
//                                     const StuffedWhippleDesignInput&);
//   Thesis step 2 (ThesisSizing.hpp)
//     ThesisSizingResult thesisMassSplits(const FoamPanelSpec&, const Threat&,
//                                         const ThesisSizingOptions& = {});
//     InitialStandoffResult thesisInitialStandoff(const FoamPanelSpec&, const Threat&,
//                                                 double standoffMinCm, double standoffMaxCm,
//                                                 const ThesisSizingOptions& = {});
//     (ThesisSizingOptions{convention, shatterConstants}: ThesisInverted + Printed reproduce
//      the reference's Table V and S_initial digits; the defaults are Handbook + Continuous.)
//     double equivalentSolidFoamCm(const FoamPanelSpec&, double coreThicknessCm);
//     double equivalentTotalPlateCm(const FoamPanelSpec&, double coreThicknessCm);
//     const char* massSplitName(MassSplitModel);
//   Curves (BallisticLimitCurve.hpp)
//     BallisticLimitCurve sampleBallisticLimitCurve(
//         const std::function<CriticalDiameterResult(double velocityKmS)>&,
//         double vMinKmS = 0.5, double vMaxKmS = 15.0, std::size_t count = 100);
//   Root finding (RootFinding.hpp)
//     RootResult brentRoot(const std::function<double(double)>&, double lo, double hi,
//                          double xTol = 1e-12, int maxIterations = 200);
//
// Example, a Whipple ballistic limit curve:
//   hvi::ble::WhippleShield shield{0.127, 2.7, 0.318, 40.0, 10.0};
//   hvi::ble::Threat threat{0.0, 2.7, 7.0, 0.0};
//   auto curve = hvi::ble::sampleBallisticLimitCurve([&](double v) {
//       auto t = threat;
//       t.velocityKmS = v;
//       return hvi::ble::whippleNnoCriticalDiameter(shield, t);
//   });
#pragma once

#include "ble/BallisticLimitCurve.hpp"
#include "ble/FoamSandwich.hpp"
#include "ble/HoneycombSandwich.hpp"
#include "ble/RootFinding.hpp"
#include "ble/SingleWall.hpp"
#include "ble/StuffedWhipple.hpp"
#include "ble/ThesisSizing.hpp"
#include "ble/Types.hpp"
#include "ble/WhippleDesign.hpp"
#include "ble/WhippleNno.hpp"
