// SPDX-License-Identifier: MIT
#include "tcl/commands/TclResult.h"

namespace dabs::tcl {

void setResult(Runtime& rt, int value) { Tcl_SetObjResult(rt.interp, Tcl_NewIntObj(value)); }

void setResult(Runtime& rt, double value) { Tcl_SetObjResult(rt.interp, Tcl_NewDoubleObj(value)); }

void setResult(Runtime& rt, const std::string& value) {
  Tcl_SetObjResult(rt.interp, Tcl_NewStringObj(value.c_str(), static_cast<int>(value.size())));
}

void setResult(Runtime& rt, const std::vector<double>& values) {
  Tcl_Obj* list = Tcl_NewListObj(0, nullptr);
  for (double v : values) Tcl_ListObjAppendElement(nullptr, list, Tcl_NewDoubleObj(v));
  Tcl_SetObjResult(rt.interp, list);
}

void setResult(Runtime& rt, const std::vector<int>& values) {
  Tcl_Obj* list = Tcl_NewListObj(0, nullptr);
  for (int v : values) Tcl_ListObjAppendElement(nullptr, list, Tcl_NewIntObj(v));
  Tcl_SetObjResult(rt.interp, list);
}

void setResult(Runtime& rt, const Eigen::Ref<const Eigen::VectorXd>& values) {
  Tcl_Obj* list = Tcl_NewListObj(0, nullptr);
  for (Eigen::Index i = 0; i < values.size(); ++i)
    Tcl_ListObjAppendElement(nullptr, list, Tcl_NewDoubleObj(values(i)));
  Tcl_SetObjResult(rt.interp, list);
}

}  // namespace dabs::tcl
