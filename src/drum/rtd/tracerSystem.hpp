// A linear tracer network dy/dt = K y + b u(t), E(t) = c y(t): y holds the
// tracer mass in each compartment, u is the tracer injection rate into the
// feed compartment (unit total injection), c the fractional outflow rates
// to the product. Any compartment model at steady bulk flow gives one.
#ifndef DRUM_RTD_TRACERSYSTEM_HPP
#define DRUM_RTD_TRACERSYSTEM_HPP

#include <Eigen/Dense>
#include <Eigen/Sparse>

namespace drum
{

struct TracerSystem
{
    Eigen::SparseMatrix<double> K;  //!< compartment rate matrix, 1/s (Metzler, column sums <= 0)
    Eigen::VectorXd b;              //!< where injected tracer enters (sums to 1)
    Eigen::RowVectorXd c;           //!< fractional outflow rate to the outlet, 1/s

    Eigen::Index size() const { return b.size(); }
};

} // namespace drum

#endif
