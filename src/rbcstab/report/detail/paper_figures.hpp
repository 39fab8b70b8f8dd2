#pragma once
// The paper's figures (module-private), each composed by one function into the Composer: its runs, data files,
// panels, caption and claims. build_paper (paper.cpp) calls them in the paper's order; figure k of n is the
// progress step.
#include "rbcstab/report/detail/paper_composer.hpp"

namespace rbcstab::detail::paper {

void fig2(Composer& c, int k, int n);                   // paper_fig2.cpp
void fig3(Composer& c, int k, int n);                   // paper_fig3.cpp
void fig4(Composer& c, int k, int n);                   // paper_fig4_appE.cpp
void fig5(Composer& c, int k, int n);                   // paper_fig5.cpp
void fig6(Composer& c, int k, int n);                   // paper_fig6.cpp
void app_vesicle(Composer& c, bool ip, int k, int n);   // paper_appC.cpp: Fig. app3 (OP), Fig. app4 (IP)
void app_in_plane_diagrams(Composer& c, int k, int n);  // paper_fig4_appE.cpp: Fig. app1
void app_suppressed(Composer& c, int k, int n);         // paper_appF.cpp: Fig. app2

}  // namespace rbcstab::detail::paper
