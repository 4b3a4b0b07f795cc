function r = slow_flow_clearance_for_response_d_Omega(M, K, C, m, e, F0, X_b, Omega, xi)
% SLOW_FLOW_CLEARANCE_FOR_RESPONSE_D_OMEGA  ∂/∂Omega of: clearance d at which the primary's amplitude is ξ·d/2 at Ω (the response surface) (its partial derivative in forcing frequency Ω) [m s/rad], Eq. F5 (derived here, beyond the paper).
%
%   r = slow_flow_clearance_for_response_d_Omega(M, K, C, m, e, F0, X_b, Omega, xi)
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
% \partial d / \partial \Omega = \partial d / \partial \Omega = \frac{2 C^{2} \Omega X_{b}^{2} \xi}{\sqrt{C^{2} \Omega^{2} X_{b}^{2} + \left(F_{0} + K X_{b}\right)^{2}} \sqrt{\left(C \Omega \xi^{2} - \frac{16 \Omega^{2} m \left(e - 1\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)^{2}}{\pi^{3} \left(e + 1\right) \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)^{2}}\right)^{2} + \left(- \frac{8 \Omega^{2} m \left(-1 + \frac{\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1}{\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1}\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)}{\pi^{2} \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)} + \xi^{2} \left(K - M \Omega^{2}\right)\right)^{2}}} + \frac{2 \xi \left(- \frac{\left(2 C \xi^{2} - \frac{64 \Omega m \left(e - 1\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)^{2}}{\pi^{3} \left(e + 1\right) \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)^{2}}\right) \left(C \Omega \xi^{2} - \frac{16 \Omega^{2} m \left(e - 1\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)^{2}}{\pi^{3} \left(e + 1\right) \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)^{2}}\right)}{2} - \frac{\left(- 4 M \Omega \xi^{2} - \frac{32 \Omega m \left(-1 + \frac{\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1}{\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1}\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)}{\pi^{2} \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)}\right) \left(- \frac{8 \Omega^{2} m \left(-1 + \frac{\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1}{\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1}\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)}{\pi^{2} \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)} + \xi^{2} \left(K - M \Omega^{2}\right)\right)}{2}\right) \sqrt{C^{2} \Omega^{2} X_{b}^{2} + \left(F_{0} + K X_{b}\right)^{2}}}{\left(\left(C \Omega \xi^{2} - \frac{16 \Omega^{2} m \left(e - 1\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)^{2}}{\pi^{3} \left(e + 1\right) \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)^{2}}\right)^{2} + \left(- \frac{8 \Omega^{2} m \left(-1 + \frac{\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1}{\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1}\right) \left(\sqrt{\frac{4 \xi^{2} \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + \xi^{2} - \frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}}} + 1\right)}{\pi^{2} \left(\frac{4 \left(e - 1\right)^{2}}{\pi^{2} \left(e + 1\right)^{2}} + 1\right)} + \xi^{2} \left(K - M \Omega^{2}\right)\right)^{2}\right)^{\frac{3}{2}}}
%
% Generated by derive/slow_flow.py through derive/templates/octave/kernel.m.j2.
% Do not edit by hand: change the derivation and run `python -m derive`.
% Mirrors symimpact.generated.slow_flow.clearance_for_response_d_Omega; operations: 87.
  x_0 = Omega.^2;
  x_1 = C.^2.*X_b.^2;
  x_2 = sqrt(x_0.*x_1 + (F0 + K.*X_b).^2);
  x_3 = xi.^2;
  x_4 = C.*x_3;
  x_5 = m.*x_0;
  x_6 = e + 1;
  x_7 = pi^(-2);
  x_8 = e - 1;
  x_9 = 4*x_7.*x_8.^2./x_6.^2;
  x_10 = sqrt(x_3.*x_9 + x_3 - x_9) + 1;
  x_11 = x_9 + 1;
  x_12 = x_10.^2.*x_8./(pi^3*x_11.^2.*x_6);
  x_13 = Omega.*x_4 - 16*x_12.*x_5;
  x_14 = 1./x_11;
  x_15 = x_10.*x_14.*x_7.*(x_10.*x_14 - 1);
  x_16 = -8*x_15.*x_5 + x_3.*(K - M.*x_0);
  x_17 = x_13.^2 + x_16.^2;
  x_18 = 2*xi;
  x_19 = Omega.*m;
  r = Omega.*x_1.*x_18./(sqrt(x_17).*x_2) + x_18.*x_2.*(-x_13.*(-64*x_12.*x_19 + 2*x_4)/2 - x_16.*(-4*M.*Omega.*x_3 - 32*x_15.*x_19)/2)./x_17.^(3/2);
  r = r + zeros(size(M + K + C + m + e + F0 + X_b + Omega + xi));
  if ~isreal(r)
    r(imag(r) ~= 0) = NaN;
    r = real(r);
  end
end
