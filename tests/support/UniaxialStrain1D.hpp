// An independent one-dimensional reference for plate-impact tests in uniaxial strain: a
// Lagrangian staggered-grid hydrocode (von Neumann and Richtmyer, J. Appl. Phys. 21 (1950)
// 232, with a Landshoff linear term), written from the formulas only and sharing no code with
// libcore, so that the FE package's planar results can be checked against it.
//
// Model: Mie-Grueneisen with b = 0 (the compressed branch
//   P = rho0 c0^2 mu [1 + (1 - Gamma0/2) mu] / [1 - (s - 1) mu]^2 + Gamma0 rho0 e,
// the linear one P = rho0 c0^2 mu + Gamma0 rho0 e in expansion; Steinberg's form), Johnson-Cook
// flow stress Y = (A + B eps_p^n)(1 + C ln max(eps_dot / eps_dot_0, 1))(1 - T*^m) with
// T = T_room + e / c_v, elastic-plastic in uniaxial strain: the axial deviator s grows at
// (4/3) G D and is held at |s| <= 2Y/3 (von Mises, the lateral deviators are -s/2), the
// equivalent strain rate is (2/3)|D|. A cell spalls when its largest principal stress
// -P + max(s, -s/2) exceeds sigma_sp: it then carries no deviator and no tension. Flyer and
// target meet at a contact that transmits compression only (inelastic, momentum-conserving).
// The energy update is exact for an EOS linear in e (a trapezoidal pressure solved for e_1).
//
// Units: mm, us, g/cm^3, km/s, GPa, MJ/kg (as libcore).
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace hvi::test {

struct UniaxialMaterial {
    double rho0, c0, s, gamma0;       ///< g/cm^3, km/s, -, -
    double shearGPa;                  ///< G
    double aGPa, bGPa, n, c, m;       ///< Johnson-Cook strength
    double referenceRatePerUs;        ///< eps_dot_0
    double specificHeat;              ///< c_v [MJ/(kg K)]
    double roomK, meltK;              ///< T_room, T_melt
    double spallGPa;                  ///< sigma_sp (<= 0: no spall)
};

struct UniaxialPlateImpact {
    double flyerMm, targetMm, speedKmS, cellMm;
    double cq = 1.5, cl = 0.06; ///< quadratic and linear viscosity coefficients
    double cfl = 0.4;
};

class UniaxialStrain1D {
public:
    UniaxialStrain1D(const UniaxialMaterial& mat, const UniaxialPlateImpact& setup)
        : m_mat(mat), m_setup(setup) {
        const int nf = static_cast<int>(std::lround(setup.flyerMm / setup.cellMm));
        const int nt = static_cast<int>(std::lround(setup.targetMm / setup.cellMm));
        m_flyerCells = nf;
        const int cells = nf + nt;
        // Nodes 0..nf are the flyer's, nf+1..cells+1 the target's (the contact splits node nf).
        for (int i = 0; i <= nf; ++i) {
            m_x.push_back(-setup.flyerMm + i * setup.cellMm);
            m_v.push_back(setup.speedKmS);
        }
        for (int i = 0; i <= nt; ++i) {
            m_x.push_back(i * setup.cellMm);
            m_v.push_back(0.0);
        }
        m_cellMass.assign(static_cast<std::size_t>(cells), mat.rho0 * setup.cellMm);
        m_e.assign(m_cellMass.size(), 0.0);
        m_sDev.assign(m_cellMass.size(), 0.0);
        m_epsP.assign(m_cellMass.size(), 0.0);
        m_p.assign(m_cellMass.size(), 0.0);
        m_q.assign(m_cellMass.size(), 0.0);
        m_failed.assign(m_cellMass.size(), false);
        m_width.assign(m_cellMass.size(), setup.cellMm);
    }

    double freeSurfaceVelocity() const { return m_v.back(); }
    /// Largest principal stress [GPa] any unfailed target cell has carried so far.
    double maxTensionGPa() const { return m_maxTension; }
    /// Kinetic plus internal energy per unit area [J/mm^2] (the kinetic part from the
    /// half-step velocities, so it is exact only to O(dt)).
    double totalEnergy() const {
        double sum = 0.0;
        for (std::size_t k = 0; k < m_cellMass.size(); ++k) {
            const double vl = m_v[left(k)], vr = m_v[right(k)];
            sum += m_cellMass[k] * (m_e[k] + 0.25 * (vl * vl + vr * vr));
        }
        return sum;
    }

    /// Runs to `endUs`, calling `sample(*this)` after every step.
    void run(double endUs, const std::function<void(const UniaxialStrain1D&)>& sample) {
        while (m_t < endUs) {
            step(std::min(stableStep(), endUs - m_t));
            sample(*this);
        }
    }

private:
    // Node index of cell k's left and right nodes (cells of the target start after the
    // flyer's last node, so the contact is a pair of nodes).
    std::size_t left(std::size_t k) const { return k < m_flyerCells ? k : k + 1; }
    std::size_t right(std::size_t k) const { return left(k) + 1; }

    double coldPressure(double mu, double* slope) const {
        const double k = m_mat.rho0 * m_mat.c0 * m_mat.c0;
        if (mu <= 0.0) {
            *slope = k;
            return k * mu;
        }
        const double a = 1.0 - 0.5 * m_mat.gamma0, sm1 = m_mat.s - 1.0;
        const double den = 1.0 - sm1 * mu;
        const double num = mu * (1.0 + a * mu);
        *slope = k * ((1.0 + 2.0 * a * mu) / (den * den) + 2.0 * sm1 * num / (den * den * den));
        return k * num / (den * den);
    }

    double soundSpeed(std::size_t k) const {
        const double rho = m_cellMass[k] / m_width[k];
        double slope = 0.0;
        coldPressure(rho / m_mat.rho0 - 1.0, &slope);
        const double p = m_p[k];
        double c2 = slope / m_mat.rho0 + p * m_mat.rho0 * m_mat.gamma0 / (rho * rho);
        if (!m_failed[k]) {
            c2 += 4.0 * m_mat.shearGPa / (3.0 * rho);
        }
        return std::sqrt(std::max(c2, 0.0));
    }

    double stableStep() const {
        double dt = 1e30;
        for (std::size_t k = 0; k < m_cellMass.size(); ++k) {
            const double dv = std::fabs(m_v[right(k)] - m_v[left(k)]);
            const double c = soundSpeed(k);
            dt = std::min(dt, m_width[k] / (c * (1.0 + m_setup.cl) + 2.0 * m_setup.cq * m_setup.cq * dv));
        }
        return m_setup.cfl * dt;
    }

    double flowStress(std::size_t k, double rate) const {
        const double tStar = std::clamp(m_e[k] / m_mat.specificHeat / (m_mat.meltK - m_mat.roomK), 0.0, 1.0);
        const double ratio = rate / m_mat.referenceRatePerUs;
        const double rateFactor = ratio > 1.0 ? 1.0 + m_mat.c * std::log(ratio) : 1.0;
        const double hardening = m_mat.aGPa + (m_epsP[k] > 0.0 ? m_mat.bGPa * std::pow(m_epsP[k], m_mat.n) : 0.0);
        return hardening * rateFactor * (1.0 - std::pow(tStar, m_mat.m));
    }

    double stress(std::size_t k) const { return -(m_p[k] + m_q[k]) + m_sDev[k]; }

    void step(double dt) {
        // Kick with the forces of the current stresses (velocities live at half steps), then
        // drift. Node masses are half of each adjacent cell.
        const std::size_t nodes = m_x.size();
        std::vector<double> force(nodes, 0.0), mass(nodes, 0.0);
        for (std::size_t k = 0; k < m_cellMass.size(); ++k) {
            const double sig = stress(k);
            force[left(k)] += sig; // tension pulls the cell's nodes together
            force[right(k)] -= sig;
            mass[left(k)] += 0.5 * m_cellMass[k];
            mass[right(k)] += 0.5 * m_cellMass[k];
        }
        for (std::size_t i = 0; i < nodes; ++i) {
            m_v[i] += dt * force[i] / mass[i];
        }
        // Contact: the flyer's last node and the target's first move together while they
        // touch and would otherwise close (compression only).
        const std::size_t f = m_flyerCells, t = m_flyerCells + 1;
        if (m_x[t] - m_x[f] <= 1e-12 && m_v[f] > m_v[t]) {
            const double common = (mass[f] * m_v[f] + mass[t] * m_v[t]) / (mass[f] + mass[t]);
            m_v[f] = m_v[t] = common;
        }
        for (std::size_t i = 0; i < nodes; ++i) {
            m_x[i] += dt * m_v[i];
        }
        for (std::size_t k = 0; k < m_cellMass.size(); ++k) {
            updateCell(k, dt);
        }
        m_t += dt;
    }

    void updateCell(std::size_t k, double dt) {
        const double w0 = m_width[k];
        const double w1 = m_x[right(k)] - m_x[left(k)];
        const double dvel = m_v[right(k)] - m_v[left(k)];
        const double d = dvel / (0.5 * (w0 + w1)); // axial strain rate at the half step
        m_width[k] = w1;
        const double rho1 = m_cellMass[k] / w1;
        const double c = soundSpeed(k);
        m_q[k] = dvel < 0.0 ? rho1 * (m_setup.cq * m_setup.cq * dvel * dvel - m_setup.cl * c * dvel) : 0.0;
        // Deviator: elastic trial, then return to the yield surface.
        double sDev = m_failed[k] ? 0.0 : m_sDev[k] + dt * (4.0 / 3.0) * m_mat.shearGPa * d;
        const double rate = (2.0 / 3.0) * std::fabs(d);
        if (!m_failed[k]) {
            const double y = flowStress(k, rate);
            const double eq = 1.5 * std::fabs(sDev);
            if (eq > y) {
                m_epsP[k] += (eq - y) / (3.0 * m_mat.shearGPa);
                sDev *= y / eq;
            }
        }
        // Energy: de = (-(P-bar + q) D + s-bar D) dt / rho-bar per unit mass, P-bar the mean of
        // the start and end pressures, solved exactly since P is linear in e.
        const double dVperM = (w1 - w0) / m_cellMass[k];
        const double work = 0.5 * (m_sDev[k] + sDev) * dVperM;
        double slope = 0.0;
        const double cold = coldPressure(rho1 / m_mat.rho0 - 1.0, &slope);
        const double g = m_mat.rho0 * m_mat.gamma0;
        double e1 = (m_e[k] - (0.5 * (m_p[k] + cold) + m_q[k]) * dVperM + work) / (1.0 + 0.5 * g * dVperM);
        double p1 = cold + g * e1;
        if (m_failed[k] && p1 < 0.0) {
            // Failed material carries no tension, so none does work either.
            p1 = 0.0;
            e1 = m_e[k] - (0.5 * m_p[k] + m_q[k]) * dVperM + work;
        }
        m_e[k] = e1;
        m_p[k] = p1;
        m_sDev[k] = sDev;
        if (!m_failed[k]) {
            const double sigma1 = -p1 + std::max(sDev, -0.5 * sDev);
            if (m_mat.spallGPa > 0.0 && sigma1 > m_mat.spallGPa) {
                m_failed[k] = true;
                m_sDev[k] = 0.0;
                m_p[k] = std::max(p1, 0.0);
            } else if (k >= m_flyerCells) {
                m_maxTension = std::max(m_maxTension, sigma1);
            }
        }
    }

    UniaxialMaterial m_mat;
    UniaxialPlateImpact m_setup;
    std::size_t m_flyerCells = 0;
    std::vector<double> m_x, m_v;                            ///< nodes
    std::vector<double> m_cellMass, m_width, m_e, m_sDev, m_epsP, m_p, m_q; ///< cells
    std::vector<bool> m_failed;
    double m_t = 0.0;
    double m_maxTension = 0.0;
};

} // namespace hvi::test
