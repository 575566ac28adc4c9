// Carrier of the shared precompiled test header (tests/support/test_pch.hpp).
