function r = slow_flow_clearance_for_response_d_e(M, K, C, m, e, F0, X_b, Omega, xi)
% SLOW_FLOW_CLEARANCE_FOR_RESPONSE_D_E  ∂/∂e of: clearance d at which the primary's amplitude is ξ·d/2 at Ω (the response surface) (its partial derivative in coefficient of restitution e) [m], Eq. F5 (derived here, beyond the paper).
%
%   r = slow_flow_clearance_for_response_d_e(M, K, C, m, e, F0, X_b, Omega, xi)
%
% Arguments (scalars or arrays of compatible sizes, SI units):
%   M: Main mass M [kg]
%   K: Main stiffness K [N/m]
%   C: Main damping C (underdamped) [N s/m]
%   m: Impact mass m [kg]
%   e: Coefficient of restitution e [1]
%   F0: Force amplitude F0 on the main mass [N]
%   X_b: Base-motion amplitude X_b [m]
%   Omega: Forcing frequency Ω [rad/s]
%   xi: Primary amplitude over half the clearance ξ [1]
%
% Returns an array of the broadcast size; NaN where the result is not real.
% \partial d / \partial e = \partial d / \partial e = \frac{2 \xi \left(- \frac{\left(C \Omega \xi^{2} - \frac{16 \Omega^{2} m \left(e - 1\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)^{2}}{\pi^{3} \left(e + 1\right) \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)^{2}}\right) \left(- \frac{32 \Omega^{2} m \left(e - 1\right) \left(\frac{16 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{3}} - \frac{8 \left(2 e - 2\right)}{\pi^{2} \left(e + 1\right)^{2}}\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)^{2}}{\pi^{3} \left(e + 1\right) \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)^{3}} - \frac{64 \Omega^{2} m \left(e - 1\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right) \left(- \frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{3}} + \frac{2 \xi^{2} \left(2 e - 2\right)}{\pi^{2} \left(e + 1\right)^{2}} + \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{3}} - \frac{2 \left(2 e - 2\right)}{\pi^{2} \left(e + 1\right)^{2}}\right)}{\pi^{3} \left(e + 1\right) \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)^{2} \sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}}} + \frac{32 \Omega^{2} m \left(e - 1\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)^{2}}{\pi^{3} \left(e + 1\right)^{2} \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)^{2}} - \frac{32 \Omega^{2} m \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)^{2}}{\pi^{3} \left(e + 1\right) \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)^{2}}\right)}{2} - \frac{\left(- \frac{8 \Omega^{2} m \left(-1 + \frac{\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1}{\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1}\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)}{\pi^{2} \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)} + \xi^{2} \left(K - M \Omega^{2}\right)\right) \left(- \frac{16 \Omega^{2} m \left(-1 + \frac{\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1}{\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1}\right) \left(\frac{8 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{3}} - \frac{4 \left(2 e - 2\right)}{\pi^{2} \left(e + 1\right)^{2}}\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)}{\pi^{2} \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)^{2}} - \frac{16 \Omega^{2} m \left(-1 + \frac{\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1}{\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1}\right) \left(- \frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{3}} + \frac{2 \xi^{2} \left(2 e - 2\right)}{\pi^{2} \left(e + 1\right)^{2}} + \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{3}} - \frac{2 \left(2 e - 2\right)}{\pi^{2} \left(e + 1\right)^{2}}\right)}{\pi^{2} \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right) \sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}}} - \frac{16 \Omega^{2} m \left(\frac{\left(\frac{8 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{3}} - \frac{4 \left(2 e - 2\right)}{\pi^{2} \left(e + 1\right)^{2}}\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)}{\left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)^{2}} + \frac{- \frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{3}} + \frac{2 \xi^{2} \left(2 e - 2\right)}{\pi^{2} \left(e + 1\right)^{2}} + \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{3}} - \frac{2 \left(2 e - 2\right)}{\pi^{2} \left(e + 1\right)^{2}}}{\left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right) \sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}}}\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)}{\pi^{2} \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)}\right)}{2}\right) \sqrt{C^{2} \Omega^{2} X_{b}^{2} + \left(F_{0} + K X_{b}\right)^{2}}}{\left(\left(C \Omega \xi^{2} - \frac{16 \Omega^{2} m \left(e - 1\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)^{2}}{\pi^{3} \left(e + 1\right) \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)^{2}}\right)^{2} + \left(- \frac{8 \Omega^{2} m \left(-1 + \frac{\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1}{\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1}\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)}{\pi^{2} \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)} + \xi^{2} \left(K - M \Omega^{2}\right)\right)^{2}\right)^{\frac{3}{2}}}
%
% Generated by derive/slow_flow.py through derive/templates/octave/kernel.m.j2.
% Do not edit by hand: change the derivation and run `python -m derive`.
% Mirrors symimpact.generated.slow_flow.clearance_for_response_d_e; operations: 133.
  x_0 = Omega.^2;
  x_1 = xi.^2;
  x_2 = e - 1;
  x_3 = pi^(-2);
  x_4 = e + 1;
  x_5 = x_4.^(-2);
  x_6 = x_3.*x_5;
  x_7 = x_2.^2;
  x_8 = 4*x_7;
  x_9 = x_6.*x_8;
  x_10 = x_9 + 1;
  x_11 = x_10.^(-2);
  x_12 = sqrt(x_1.*x_9 + x_1 - x_9);
  x_13 = x_12 + 1;
  x_14 = x_13.^2;
  x_15 = pi^(-3);
  x_16 = m.*x_0;
  x_17 = x_15.*x_16./x_4;
  x_18 = x_11.*x_14.*x_17;
  x_19 = C.*Omega.*x_1 - 16*x_18.*x_2;
  x_20 = 1./x_10;
  x_21 = x_13.*x_20 - 1;
  x_22 = x_13.*x_16.*x_20.*x_3;
  x_23 = x_1.*(K - M.*x_0) - 8*x_21.*x_22;
  x_24 = x_4.^(-3);
  x_25 = x_24.*x_3;
  x_26 = x_25.*x_7;
  x_27 = 2*e - 2;
  x_28 = x_27.*x_6;
  x_29 = (-x_1.*x_25.*x_8 + 2*x_1.*x_27.*x_3.*x_5 + 4*x_24.*x_3.*x_7 - 2*x_28)./x_12;
  x_30 = x_11.*x_13;
  x_31 = x_30.*(8*x_26 - 4*x_28);
  x_32 = 16*x_16.*x_21.*x_3;
  x_33 = x_20.*x_29;
  r = 2*xi.*(-x_19.*(32*m.*x_0.*x_11.*x_14.*x_15.*x_2.*x_5 - 64*x_17.*x_2.*x_29.*x_30 - 32*x_18 - 32*x_14.*x_17.*x_2.*(16*x_26 - 8*x_28)./x_10.^3)/2 - x_23.*(-16*x_22.*(x_31 + x_33) - x_31.*x_32 - x_32.*x_33)/2).*sqrt(C.^2.*X_b.^2.*x_0 + (F0 + K.*X_b).^2)./(x_19.^2 + x_23.^2).^(3/2);
  r = r + zeros(size(M + K + C + m + e + F0 + X_b + Omega + xi));
  if ~isreal(r)
    r(imag(r) ~= 0) = NaN;
    r = real(r);
  end
end
