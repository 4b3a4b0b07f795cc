function r = forced_flight_forced_displacement_d_Omega(t, M, K, C, F0, X_b, Omega, phi, x0, xdot0)
% FORCED_FLIGHT_FORCED_DISPLACEMENT_D_OMEGA  ∂/∂Omega of: main-mass displacement x(t) in forced free flight (its partial derivative in forcing frequency Ω) [m s/rad], Eq. F1 (derived here, beyond the paper).
%
%   r = forced_flight_forced_displacement_d_Omega(t, M, K, C, F0, X_b, Omega, phi, x0, xdot0)
%
% Arguments (scalars or arrays of compatible sizes, SI units):
%   t: Time since the last event [s]
%   M: Main mass M [kg]
%   K: Main stiffness K [N/m]
%   C: Main damping C (underdamped: C < 2√(KM)) [N s/m]
%   F0: Force amplitude F0 on the main mass [N]
%   X_b: Base-motion amplitude X_b [m]
%   Omega: Forcing frequency Ω [rad/s]
%   phi: Forcing phase at t = 0, φ [rad]
%   x0: Main-mass displacement at t = 0 [m]
%   xdot0: Main-mass velocity at t = 0 [m/s]
%
% Returns an array of the broadcast size; NaN where the result is not real.
% \partial x(t) / \partial \Omega = \partial x(t) / \partial \Omega = \begin{cases} \frac{F_{0} \Omega^{2} t^{2} \cos{\left(\Omega t + \phi \right)} - F_{0} \Omega t \sin{\left(\Omega t + \phi \right)} + F_{0} \sin{\left(\phi \right)} \sin{\left(\Omega t \right)} + M \Omega^{4} X_{b} t^{2} \cos{\left(\Omega t + \phi \right)} - M \Omega^{3} X_{b} t \sin{\left(\Omega t + \phi \right)} + M \Omega^{2} X_{b} \sin{\left(\phi \right)} \sin{\left(\Omega t \right)}}{4 M \Omega^{3}} & \text{for}\: C = 0 \wedge K = M \Omega^{2} \\- \frac{t \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \sin{\left(\Omega t + \phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} + \frac{t \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \cos{\left(\Omega t + \phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} + \frac{\left(- 2 C^{2} \Omega + 4 M \Omega \left(K - M \Omega^{2}\right)\right) \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \cos{\left(\Omega t + \phi \right)}}{\left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)^{2}} + \frac{\left(- 2 C^{2} \Omega + 4 M \Omega \left(K - M \Omega^{2}\right)\right) \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \sin{\left(\Omega t + \phi \right)}}{\left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)^{2}} + \left(\left(- \frac{\left(- 2 C^{2} \Omega + 4 M \Omega \left(K - M \Omega^{2}\right)\right) \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \cos{\left(\phi \right)}}{\left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)^{2}} - \frac{\left(- 2 C^{2} \Omega + 4 M \Omega \left(K - M \Omega^{2}\right)\right) \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \sin{\left(\phi \right)}}{\left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)^{2}} - \frac{\left(2 C^{2} \Omega X_{b} - 2 M \Omega \left(F_{0} + K X_{b}\right)\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\left(2 C M \Omega^{2} X_{b} - C X_{b} \left(K - M \Omega^{2}\right) + C \left(F_{0} + K X_{b}\right)\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}}\right) \cos{\left(t \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \right)} + \frac{\left(\frac{C \left(- \frac{\left(- 2 C^{2} \Omega + 4 M \Omega \left(K - M \Omega^{2}\right)\right) \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \cos{\left(\phi \right)}}{\left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)^{2}} - \frac{\left(- 2 C^{2} \Omega + 4 M \Omega \left(K - M \Omega^{2}\right)\right) \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \sin{\left(\phi \right)}}{\left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)^{2}} - \frac{\left(2 C^{2} \Omega X_{b} - 2 M \Omega \left(F_{0} + K X_{b}\right)\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\left(2 C M \Omega^{2} X_{b} - C X_{b} \left(K - M \Omega^{2}\right) + C \left(F_{0} + K X_{b}\right)\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}}\right)}{2 M} + \frac{\Omega \left(- 2 C^{2} \Omega + 4 M \Omega \left(K - M \Omega^{2}\right)\right) \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \sin{\left(\phi \right)}}{\left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)^{2}} - \frac{\Omega \left(- 2 C^{2} \Omega + 4 M \Omega \left(K - M \Omega^{2}\right)\right) \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \cos{\left(\phi \right)}}{\left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)^{2}} + \frac{\Omega \left(2 C^{2} \Omega X_{b} - 2 M \Omega \left(F_{0} + K X_{b}\right)\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\Omega \left(2 C M \Omega^{2} X_{b} - C X_{b} \left(K - M \Omega^{2}\right) + C \left(F_{0} + K X_{b}\right)\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} + \frac{\left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}}\right) \sin{\left(t \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \right)}}{\sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}\right) e^{- \frac{C t}{2 M}} + \frac{\left(2 C^{2} \Omega X_{b} - 2 M \Omega \left(F_{0} + K X_{b}\right)\right) \cos{\left(\Omega t + \phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} + \frac{\left(2 C M \Omega^{2} X_{b} - C X_{b} \left(K - M \Omega^{2}\right) + C \left(F_{0} + K X_{b}\right)\right) \sin{\left(\Omega t + \phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} & \text{otherwise} \end{cases}
%
% Generated by derive/forced_flight.py through derive/templates/octave/kernel.m.j2.
% Do not edit by hand: change the derivation and run `python -m derive`.
% Mirrors symimpact.generated.forced_flight.forced_displacement_d_Omega; operations: 136.
  x_0 = 1./M;
  x_1 = Omega.^3;
  x_2 = sin(phi);
  x_3 = Omega.*t;
  x_4 = x_2.*sin(x_3);
  x_5 = phi + x_3;
  x_6 = sin(x_5);
  x_7 = Omega.^2;
  x_8 = M.*x_7;
  x_9 = cos(x_5);
  x_10 = t.^2.*x_9;
  x_11 = M.*X_b;
  x_12 = C.^2;
  x_13 = 2*Omega;
  x_14 = x_12.*x_13;
  x_15 = F0 + K.*X_b;
  x_16 = -M.*x_13.*x_15 + X_b.*x_14;
  x_17 = x_12.*x_7;
  x_18 = K - x_8;
  x_19 = x_17 + x_18.^2;
  x_20 = 1./x_19;
  x_21 = x_20.*x_9;
  x_22 = C.*X_b;
  x_23 = x_18.*x_22;
  x_24 = C.*Omega.*x_15 - Omega.*x_23;
  x_25 = X_b.*x_17 + x_15.*x_18;
  x_26 = x_20.*x_6;
  x_27 = C.*x_15 + 2*x_22.*x_8 - x_23;
  x_28 = (4*M.*Omega.*x_18 - x_14)./x_19.^2;
  x_29 = x_24.*x_28;
  x_30 = x_25.*x_28;
  x_31 = C.*x_0/2;
  x_32 = sqrt(K.*x_0 - x_12./(4*M.^2));
  x_33 = t.*x_32;
  x_34 = cos(phi);
  x_35 = x_20.*x_34;
  x_36 = x_2.*x_20;
  x_37 = -x_16.*x_35 - x_2.*x_29 - x_27.*x_36 - x_30.*x_34;
  r = pick((C == 0) & (K == x_8), x_0.*(F0.*x_10.*x_7 - F0.*x_3.*x_6 + F0.*x_4 + Omega.^4.*x_10.*x_11 + X_b.*x_4.*x_8 - t.*x_1.*x_11.*x_6)./(4*x_1), t.*x_21.*x_24 - t.*x_25.*x_26 + x_16.*x_21 + x_26.*x_27 + x_29.*x_6 + x_30.*x_9 + (x_37.*cos(x_33) + (Omega.*x_16.*x_36 + Omega.*x_2.*x_30 - Omega.*x_27.*x_35 - Omega.*x_29.*x_34 - x_24.*x_35 + x_25.*x_36 + x_31.*x_37).*sin(x_33)./x_32).*exp(-t.*x_31));
  r = r + zeros(size(t + M + K + C + F0 + X_b + Omega + phi + x0 + xdot0));
  if ~isreal(r)
    r(imag(r) ~= 0) = NaN;
    r = real(r);
  end
end

function r = pick(c, a, b)
% Element-wise selection: a where c holds, b elsewhere (the branch not taken is ignored, also
% where it is Inf or NaN).
  r = b + zeros(size(c)) + zeros(size(a));
  a = a + zeros(size(r));
  c = logical(c + zeros(size(r)));
  r(c) = a(c);
end
