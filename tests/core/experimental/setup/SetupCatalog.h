#pragma once
// Every setup of core/experimental/setup in the configurations the tests sweep (linear and
// exact geometry, both actuator sides, joint offsets, a rotated local x), with lengths of a lab
// specimen [m]. Shared by the closed-form tests and the OpenFresco comparison.

#include "core/experimental/setup/Aggregator.h"
#include "core/experimental/setup/FourActuators3d.h"
#include "core/experimental/setup/NoTransformation.h"
#include "core/experimental/setup/PlanarSetups.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace setupcatalog {

struct Case {
    std::string label;
    std::function<std::unique_ptr<hsmu::ExperimentalSetup>(std::string&)> make;
};

inline hsmu::TwoActuators2dParams two(hsmu::SetupGeometry g, bool right, double phi = 0.0) {
    hsmu::TwoActuators2dParams p;
    p.La1 = 1.5;
    p.La2 = 1.2;
    p.L = 0.6;
    p.geometry = g;
    p.actuatorsRight = right;
    p.phiLocX = phi;
    return p;
}

inline hsmu::ThreeActuators2dParams three(hsmu::SetupGeometry g, bool right, double phi = 0.0) {
    hsmu::ThreeActuators2dParams p;
    p.La1 = 1.6;
    p.La2 = 1.1;
    p.La3 = 1.3;
    p.L1 = 0.7;
    p.L2 = 0.5;
    p.geometry = g;
    p.horizontalRight = right;
    p.phiLocX = phi;
    return p;
}

inline hsmu::ThreeActuatorsJntOff2dParams jntOff(hsmu::SetupGeometry g, bool right) {
    hsmu::ThreeActuatorsJntOff2dParams p;
    p.La1 = 1.6;
    p.La2 = 1.1;
    p.La3 = 1.3;
    p.L1 = 0.2;
    p.L2 = 0.7;
    p.L3 = 0.5;
    p.L4 = 0.25;
    p.L5 = 0.3;
    p.L6 = 0.35;
    p.geometry = g;
    p.horizontalRight = right;
    return p;
}

inline hsmu::FourActuators3dParams four(hsmu::SetupGeometry g, double phi = 0.0) {
    hsmu::FourActuators3dParams p;
    p.L1 = 1.2;
    p.L2 = 1.3;
    p.L3 = 1.1;
    p.L4 = 1.4;
    p.a1 = 0.3;
    p.a2 = 0.35;
    p.a3 = 0.25;
    p.a4 = 0.4;
    p.h = 0.8;
    p.h1 = 0.45; // the axial-load rods: top pins 0.45 m up, 1.6 and 1.9 m long
    p.LrodN = 1.6;
    p.LrodS = 1.9;
    p.geometry = g;
    p.phiLocX = phi;
    return p;
}

inline std::vector<Case> all() {
    using hsmu::SetupGeometry;
    std::vector<Case> cases;
    for (SetupGeometry g : {SetupGeometry::Linear, SetupGeometry::Exact}) {
        const std::string geo = g == SetupGeometry::Exact ? " nlGeom" : "";
        for (bool right : {false, true}) {
            const std::string side = right ? " right" : " left";
            cases.push_back({"TwoActuators2d" + geo + side, [=](std::string& e) {
                                 return std::unique_ptr<hsmu::ExperimentalSetup>(
                                     hsmu::makeTwoActuators2d(two(g, right), e));
                             }});
            cases.push_back({"ThreeActuators2d" + geo + side, [=](std::string& e) {
                                 return std::unique_ptr<hsmu::ExperimentalSetup>(
                                     hsmu::makeThreeActuators2d(three(g, right), e));
                             }});
            cases.push_back({"ThreeActuatorsJntOff2d" + geo + side, [=](std::string& e) {
                                 return std::unique_ptr<hsmu::ExperimentalSetup>(
                                     hsmu::makeThreeActuatorsJntOff2d(jntOff(g, right), e));
                             }});
            cases.push_back({"InvertedVBrace2d" + geo + side, [=](std::string& e) {
                                 return std::unique_ptr<hsmu::ExperimentalSetup>(
                                     hsmu::makeInvertedVBrace2d(three(g, right), e));
                             }});
            cases.push_back({"InvertedVBraceJntOff2d" + geo + side, [=](std::string& e) {
                                 return std::unique_ptr<hsmu::ExperimentalSetup>(
                                     hsmu::makeInvertedVBraceJntOff2d(jntOff(g, right), e));
                             }});
            cases.push_back({"ChevronBrace2d" + geo + side, [=](std::string& e) {
                                 return std::unique_ptr<hsmu::ExperimentalSetup>(
                                     hsmu::makeChevronBrace2d(three(g, right), e));
                             }});
        }
        cases.push_back({"TwoActuators2d" + geo + " phiLocX 30", [=](std::string& e) {
                             return std::unique_ptr<hsmu::ExperimentalSetup>(
                                 hsmu::makeTwoActuators2d(two(g, false, 30.0), e));
                         }});
        cases.push_back({"ThreeActuators2d" + geo + " phiLocX -20", [=](std::string& e) {
                             return std::unique_ptr<hsmu::ExperimentalSetup>(
                                 hsmu::makeThreeActuators2d(three(g, false, -20.0), e));
                         }});
        for (double phi : {0.0, 25.0})
            cases.push_back({"FourActuators3d" + geo + " phiLocX " + std::to_string(int(phi)),
                             [=](std::string& e) {
                                 return std::unique_ptr<hsmu::ExperimentalSetup>(
                                     hsmu::FourActuators3d::create(four(g, phi), e));
                             }});
        cases.push_back({"Aggregator (OneActuator + ThreeActuators2d" + geo + ")",
                         [=](std::string& e) -> std::unique_ptr<hsmu::ExperimentalSetup> {
                             std::vector<std::unique_ptr<hsmu::ExperimentalSetup>> parts;
                             parts.push_back(hsmu::OneActuator::create(2, 3, e));
                             parts.push_back(hsmu::makeThreeActuators2d(three(g, true), e));
                             return hsmu::Aggregator::create(std::move(parts), e);
                         }});
    }
    cases.push_back({"NoTransformation 1 3 of 3", [](std::string& e) {
                         return std::unique_ptr<hsmu::ExperimentalSetup>(
                             hsmu::NoTransformation::create({1, 3}, 3, e));
                     }});
    cases.push_back({"OneActuator 1 of 1", [](std::string& e) {
                         return std::unique_ptr<hsmu::ExperimentalSetup>(
                             hsmu::OneActuator::create(1, 1, e));
                     }});
    return cases;
}

} // namespace setupcatalog
