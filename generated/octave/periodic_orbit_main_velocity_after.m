function r = periodic_orbit_main_velocity_after(M, K, C, m, e, d, F0, X_b, Omega, phi)
% PERIODIC_ORBIT_MAIN_VELOCITY_AFTER  Main-mass velocity V after the first impact [m/s], Eq. F3 (derived here, beyond the paper).
%
%   r = periodic_orbit_main_velocity_after(M, K, C, m, e, d, F0, X_b, Omega, phi)
%
% Arguments (scalars or arrays of compatible sizes, SI units):
%   M: Main mass M [kg]
%   K: Main stiffness K [N/m]
%   C: Main damping C (underdamped) [N s/m]
%   m: Impact mass m [kg]
%   e: Coefficient of restitution e [1]
%   d: Total clearance d [m]
%   F0: Force amplitude F0 on the main mass [N]
%   X_b: Base-motion amplitude X_b [m]
%   Omega: Forcing frequency Ω [rad/s]
%   phi: Forcing phase at the first impact φ [rad]
%
% Returns an array of the broadcast size; NaN where the result is not real.
% V = V = \frac{\Omega \left(- \frac{\pi M \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\pi M \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\pi M \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} - \frac{\pi M \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} + \frac{\pi M \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} + \frac{\pi M \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} + \frac{\pi M \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} + \frac{\pi M \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} + \frac{\pi M \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \left(- \frac{C \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}}{2 M} + \left(\frac{C \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M} - \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}\right) e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\phi \right)} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{\sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)} - \frac{\pi M \left(- \frac{C \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}}{2 M} + \left(\frac{C \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M} - \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}\right) \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)} \cos{\left(\phi \right)}}{\sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)} - \frac{4 \Omega m \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\phi \right)} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{\sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)} + \frac{4 \Omega m \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)} \cos{\left(\phi \right)}}{\sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \left(C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}\right)} + 2 d m \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}} + 2 d m + \frac{4 m \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} + \frac{4 m \left(C^{2} \Omega^{2} X_{b} + \left(F_{0} + K X_{b}\right) \left(K - M \Omega^{2}\right)\right) \cos{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} + \frac{4 m \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}} + \frac{4 m \left(- C \Omega X_{b} \left(K - M \Omega^{2}\right) + C \Omega \left(F_{0} + K X_{b}\right)\right) \sin{\left(\phi \right)}}{C^{2} \Omega^{2} + \left(K - M \Omega^{2}\right)^{2}}\right)}{\pi M \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}} + \pi M \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}} + \pi M \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) + \pi M - \frac{\pi M \left(- \frac{C \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}}{2 M} + \left(\frac{C \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M} - \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}\right) e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{\sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \frac{4 \Omega m e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{\sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}}
%
% Generated by derive/periodic_orbit.py through derive/templates/octave/kernel.m.j2.
% Do not edit by hand: change the derivation and run `python -m derive`.
% Mirrors symimpact.generated.periodic_orbit.main_velocity_after; operations: 112.
  x_0 = pi*M;
  x_1 = 4*m;
  x_2 = pi./Omega;
  x_3 = 1./M;
  x_4 = C.*x_3/2;
  x_5 = exp(-x_2.*x_4);
  x_6 = C.^2;
  x_7 = sqrt(K.*x_3 - x_6./(4*M.^2));
  x_8 = x_2.*x_7;
  x_9 = sin(x_8);
  x_10 = x_9./x_7;
  x_11 = x_10.*x_5;
  x_12 = Omega.*x_11;
  x_13 = cos(x_8);
  x_14 = x_10.*x_4;
  x_15 = x_5.*(x_13 + x_14);
  x_16 = x_0.*x_15;
  x_17 = x_0.*(x_13.*x_5 - x_14.*x_5);
  x_18 = x_15.*x_17;
  x_19 = x_11.*(-x_15.*x_4 + x_5.*(x_13.*x_4 - x_7.*x_9));
  x_20 = 2*d.*m;
  x_21 = Omega.^2;
  x_22 = x_21.*x_6;
  x_23 = K - M.*x_21;
  x_24 = 1./(x_22 + x_23.^2);
  x_25 = x_24.*sin(phi);
  x_26 = F0 + K.*X_b;
  x_27 = -C.*Omega.*X_b.*x_23 + C.*Omega.*x_26;
  x_28 = x_1.*x_27;
  x_29 = x_25.*x_28;
  x_30 = x_24.*cos(phi);
  x_31 = x_27.*x_30;
  x_32 = x_0.*x_31;
  x_33 = X_b.*x_22 + x_23.*x_26;
  x_34 = x_1.*x_33;
  x_35 = x_30.*x_34;
  x_36 = x_25.*x_33;
  x_37 = x_0.*x_36;
  r = Omega.*(-x_12.*x_25.*x_34 + x_12.*x_28.*x_30 + x_15.*x_20 + x_15.*x_29 + x_15.*x_35 + x_16.*x_31 - x_16.*x_36 + x_17.*x_31 - x_17.*x_36 + x_18.*x_31 - x_18.*x_36 - x_19.*x_32 + x_19.*x_37 + x_20 + x_29 + x_32 + x_35 - x_37)./(-x_0.*x_19 + x_0 + x_1.*x_12 + x_16 + x_17 + x_18);
  r = r + zeros(size(M + K + C + m + e + d + F0 + X_b + Omega + phi));
  if ~isreal(r)
    r(imag(r) ~= 0) = NaN;
    r = real(r);
  end
end
