// The registered identification methods, one line each: USVID_METHOD(Factory), where the method's
// folder defines `Method Factory()` (methods/method.h). Included by methods/registry.cc only;
// the order is the order of --help and of the method lists in messages.
// NOLINTBEGIN(bugprone-macro-parentheses)
USVID_METHOD(GpMethod)
USVID_METHOD(SindyMethod)
USVID_METHOD(EbLrMethod)
USVID_METHOD(FossenCeresMethod)
USVID_METHOD(RefitMethod)
USVID_METHOD(HybridMethod)
USVID_METHOD(NominalMethod)
USVID_METHOD(NomotoMethod)
USVID_METHOD(LtiMethod)
// NOLINTEND(bugprone-macro-parentheses)
