#include "Shape.H"

#include <cmath>

namespace
{

using solid::ShapeRule;

const double gp = 1.0/std::sqrt(3.0);

ShapeRule makeLine2()
{
    ShapeRule r;
    r.nen = 2;
    r.pdim = 1;
    for (double xi : {-gp, gp})
    {
        Eigen::VectorXd N(2);
        N << 0.5*(1 - xi), 0.5*(1 + xi);
        Eigen::MatrixXd d(2, 1);
        d << -0.5, 0.5;
        r.N.push_back(N);
        r.dNdxi.push_back(d);
        r.w.push_back(1.0);
    }
    return r;
}

ShapeRule makeQuad4()
{
    ShapeRule r;
    r.nen = 4;
    r.pdim = 2;
    for (double eta : {-gp, gp})
    for (double xi : {-gp, gp})
    {
        Eigen::VectorXd N;
        Eigen::MatrixXd d;
        solid::shapeAt
        (
            solid::ElementType::quad4Axi, Eigen::Vector3d(xi, eta, 0), N, d
        );
        r.N.push_back(N);
        r.dNdxi.push_back(d);
        r.w.push_back(1.0);
    }
    return r;
}

ShapeRule makeHex8()
{
    ShapeRule r;
    r.nen = 8;
    r.pdim = 3;
    for (double ze : {-gp, gp})
    for (double eta : {-gp, gp})
    for (double xi : {-gp, gp})
    {
        Eigen::VectorXd N;
        Eigen::MatrixXd d;
        solid::shapeAt
        (
            solid::ElementType::hex8, Eigen::Vector3d(xi, eta, ze), N, d
        );
        r.N.push_back(N);
        r.dNdxi.push_back(d);
        r.w.push_back(1.0);
    }
    return r;
}

} // namespace


void solid::shapeAt
(
    ElementType t,
    const Eigen::Vector3d& p,
    Eigen::VectorXd& N,
    Eigen::MatrixXd& d
)
{
    const double xi = p(0), eta = p(1), ze = p(2);
    if (t == ElementType::quad4Axi)
    {
        static const double xa[4] = {-1, 1, 1, -1};
        static const double ya[4] = {-1, -1, 1, 1};
        N.resize(4);
        d.resize(4, 2);
        for (int a = 0; a < 4; ++a)
        {
            N(a) = 0.25*(1 + xa[a]*xi)*(1 + ya[a]*eta);
            d(a, 0) = 0.25*xa[a]*(1 + ya[a]*eta);
            d(a, 1) = 0.25*ya[a]*(1 + xa[a]*xi);
        }
        return;
    }
    static const double xa[8] = {-1, 1, 1, -1, -1, 1, 1, -1};
    static const double ya[8] = {-1, -1, 1, 1, -1, -1, 1, 1};
    static const double za[8] = {-1, -1, -1, -1, 1, 1, 1, 1};
    N.resize(8);
    d.resize(8, 3);
    for (int a = 0; a < 8; ++a)
    {
        const double fx = 1 + xa[a]*xi, fy = 1 + ya[a]*eta,
            fz = 1 + za[a]*ze;
        N(a) = 0.125*fx*fy*fz;
        d(a, 0) = 0.125*xa[a]*fy*fz;
        d(a, 1) = 0.125*ya[a]*fx*fz;
        d(a, 2) = 0.125*za[a]*fx*fy;
    }
}


const solid::ShapeRule& solid::volumeRule(ElementType t)
{
    static const ShapeRule q = makeQuad4();
    static const ShapeRule h = makeHex8();
    return t == ElementType::quad4Axi ? q : h;
}


const solid::ShapeRule& solid::faceRule(ElementType t)
{
    static const ShapeRule l = makeLine2();
    static const ShapeRule q = makeQuad4();
    return t == ElementType::quad4Axi ? l : q;
}


int solid::nodesPerElement(ElementType t)
{
    return t == ElementType::quad4Axi ? 4 : 8;
}


int solid::nodesPerFace(ElementType t)
{
    return t == ElementType::quad4Axi ? 2 : 4;
}


const std::vector<std::vector<int>>& solid::elementFaces(ElementType t)
{
    // Counter-clockwise edges of the quad; hex faces with outward normal
    // (dx/dxi x dx/deta) for the gmsh node order
    static const std::vector<std::vector<int>> q =
        {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
    static const std::vector<std::vector<int>> h =
        {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5},
         {2, 3, 7, 6}, {3, 0, 4, 7}};
    return t == ElementType::quad4Axi ? q : h;
}


std::string solid::elementTypeName(ElementType t)
{
    return t == ElementType::quad4Axi ? "quad4Axi" : "hex8";
}
