function r = slow_flow_clearance_for_response_d_xi(M, K, C, m, e, F0, X_b, Omega, xi)
% SLOW_FLOW_CLEARANCE_FOR_RESPONSE_D_XI  ∂/∂xi of: clearance d at which the primary's amplitude is ξ·d/2 at Ω (the response surface) (its partial derivative in primary amplitude over half the clearance ξ) [m], Eq. F5 (derived here, beyond the paper).
%
%   r = slow_flow_clearance_for_response_d_xi(M, K, C, m, e, F0, X_b, Omega, xi)
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
% \partial d / \partial \xi = \partial d / \partial \xi = \frac{2 \xi \left(- \frac{\left(4 C \Omega \xi - \frac{64 \Omega^{2} m \left(e - 1\right) \left(\frac{4 \xi \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)}{\pi^{3} \left(e + 1\right) \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)^{2} \sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}}}\right) \left(C \Omega \xi^{2} - \frac{16 \Omega^{2} m \left(e - 1\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)^{2}}{\pi^{3} \left(e + 1\right) \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)^{2}}\right)}{2} - \frac{\left(- \frac{8 \Omega^{2} m \left(-1 + \frac{\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1}{\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1}\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)}{\pi^{2} \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)} + \xi^{2} \left(K - M \Omega^{2}\right)\right) \left(- \frac{16 \Omega^{2} m \left(-1 + \frac{\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1}{\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1}\right) \left(\frac{4 \xi \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi\right)}{\pi^{2} \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right) \sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}}} - \frac{16 \Omega^{2} m \left(\frac{4 \xi \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)}{\pi^{2} \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)^{2} \sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}}} + 4 \xi \left(K - M \Omega^{2}\right)\right)}{2}\right) \sqrt{C^{2} \Omega^{2} X_{b}^{2} + \left(F_{0} + K X_{b}\right)^{2}}}{\left(\left(C \Omega \xi^{2} - \frac{16 \Omega^{2} m \left(e - 1\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)^{2}}{\pi^{3} \left(e + 1\right) \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)^{2}}\right)^{2} + \left(- \frac{8 \Omega^{2} m \left(-1 + \frac{\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1}{\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1}\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)}{\pi^{2} \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)} + \xi^{2} \left(K - M \Omega^{2}\right)\right)^{2}\right)^{\frac{3}{2}}} + \frac{2 \sqrt{C^{2} \Omega^{2} X_{b}^{2} + \left(F_{0} + K X_{b}\right)^{2}}}{\sqrt{\left(C \Omega \xi^{2} - \frac{16 \Omega^{2} m \left(e - 1\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)^{2}}{\pi^{3} \left(e + 1\right) \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)^{2}}\right)^{2} + \left(- \frac{8 \Omega^{2} m \left(-1 + \frac{\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1}{\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1}\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)}{\pi^{2} \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)} + \xi^{2} \left(K - M \Omega^{2}\right)\right)^{2}}}
%
% Generated by derive/slow_flow.py through derive/templates/octave/kernel.m.j2.
% Do not edit by hand: change the derivation and run `python -m derive`.
% Mirrors symimpact.generated.slow_flow.clearance_for_response_d_xi; operations: 92.
  x_0 = xi.^2;
  x_1 = C.*Omega;
  x_2 = pi^(-2);
  x_3 = e + 1;
  x_4 = e - 1;
  x_5 = x_2.*x_4.^2./x_3.^2;
  x_6 = 4*x_5;
  x_7 = sqrt(x_0.*x_6 + x_0 - x_6);
  x_8 = x_7 + 1;
  x_9 = x_6 + 1;
  x_10 = x_9.^(-2);
  x_11 = 16*x_10;
  x_12 = Omega.^2;
  x_13 = m.*x_12;
  x_14 = x_13.*x_4./(pi^3*x_3);
  x_15 = x_0.*x_1 - x_11.*x_14.*x_8.^2;
  x_16 = K - M.*x_12;
  x_17 = 1./x_9;
  x_18 = x_13.*x_2;
  x_19 = x_18.*(x_17.*x_8 - 1);
  x_20 = x_0.*x_16 - 8*x_17.*x_19.*x_8;
  x_21 = x_15.^2 + x_20.^2;
  x_22 = 2*sqrt(C.^2.*X_b.^2.*x_12 + (F0 + K.*X_b).^2);
  x_23 = 4*xi;
  x_24 = (x_23.*x_5 + xi)./x_7;
  x_25 = x_24.*x_8;
  r = x_22./sqrt(x_21) + x_22.*xi.*(-x_15.*(x_1.*x_23 - 64*x_10.*x_14.*x_25)/2 - x_20.*(-x_11.*x_18.*x_25 + 4*x_16.*xi - 16*x_17.*x_19.*x_24)/2)./x_21.^(3/2);
  r = r + zeros(size(M + K + C + m + e + F0 + X_b + Omega + xi));
  if ~isreal(r)
    r(imag(r) ~= 0) = NaN;
    r = real(r);
  end
end
